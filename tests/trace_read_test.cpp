// The trace reader (trace/trace_read.hpp): what the writer writes, the
// reader reads back to the same text, for every real type, formula, spp,
// group and branch; trace files line by line; faults refused with where.
#include <catch2/catch.hpp>

#include <random>
#include <string>

#include "render/trace_pixel.hpp"
#include "scene/scene_json.hpp"
#include "trace/trace_read.hpp"
#include "util/errors.hpp"
#include "sweep_size.hpp"

using namespace promyk;

namespace {

std::string json_of(const PixelTrace& trace) {
    std::string out;
    append_trace_json(out, trace);
    return out;
}

}  // namespace

TEST_CASE("a trace read back is written as the same text", "[trace][read]") {
    const Scene everything = load_scene_file(PROMYK_SOURCE_DIR "/lessons/scenes/everything.json");
    const Scene article = load_scene_file(PROMYK_SOURCE_DIR "/lessons/scenes/article.json");
    int checked = 0;
    for (const Scene* scene : {&article, &everything})
        for (const RealType real : {RealType::float_, RealType::double_, RealType::long_double, RealType::quad_})
            for (const Formula formula : {Formula::article, Formula::stable, Formula::fma, Formula::geometric})
                for (const int spp : {1, 4})
                    for (const auto& [i, j] : {std::pair{0, 0}, {3, 4}, {5, 1}, {6, 3}, {8, 8}, {10, 2}}) {
                        const std::string text = json_of(trace_pixel(*scene, 11, i, j, real, formula, spp));
                        INFO(text);
                        const PixelTrace read = read_trace_json(text, "(test)");
                        REQUIRE(json_of(read) == text);
                        ++checked;
                    }
    CHECK(checked == 2 * 4 * 4 * 2 * 6);
}

TEST_CASE("the reader keeps a negative zero's sign and non-finite values", "[trace][read]") {
    PixelTrace trace = trace_pixel(load_scene_file(PROMYK_SOURCE_DIR "/lessons/scenes/article.json"), 8, 3, 4);
    trace.steps[0].value = Vec3d{-0.0, std::numeric_limits<double>::infinity(), std::nan("")};
    trace.steps[1].value = -0.0;
    trace.first_non_finite = first_non_finite_step(trace.steps);
    const std::string text = json_of(trace);
    REQUIRE(text.find("[-0,null,null]") != std::string::npos);
    REQUIRE(json_of(read_trace_json(text, "(test)")) == text);
}

TEST_CASE("a trace file is read line by line, and its faults are refused with the line", "[trace][read]") {
    const Scene scene = load_scene_file(PROMYK_SOURCE_DIR "/lessons/scenes/everything.json");
    const std::string a = json_of(trace_pixel(scene, 8, 1, 2, RealType::float_, Formula::article, 4));
    const std::string b = json_of(trace_pixel(scene, 8, 5, 6, RealType::float_, Formula::article, 4));
    const TraceFile file = read_trace_file(a + "\n" + b + "\n", "t.jsonl");
    REQUIRE(file.traces.size() == 2);
    REQUIRE(file.lines[1] == b);
    REQUIRE(file.traces[1].header.i == 5);
    const auto where = [](const std::string& bytes) {
        try {
            read_trace_file(bytes, "t.jsonl");
        } catch (const InputError& e) {
            return e.file + ": " + e.where;
        }
        return std::string("accepted");
    };
    const std::string other_w = json_of(trace_pixel(scene, 9, 1, 2, RealType::float_, Formula::article, 4));
    const std::string other_real = json_of(trace_pixel(scene, 8, 1, 3, RealType::double_, Formula::article, 4));
    CHECK(where(a + "\n" + other_w + "\n") == "t.jsonl: line 2");
    CHECK(where(a + "\n" + other_real + "\n") == "t.jsonl: line 2");
    CHECK(where(a + "\n" + a + "\n") == "t.jsonl: line 2");
    CHECK(where("") == "t.jsonl: ");
    CHECK(where("\n" + a.substr(0, 100) + "\n") == "t.jsonl: line 2");
    std::string unknown_key = a;
    unknown_key.replace(unknown_key.find("\"key\":\"E\""), 9, "\"key\":\"Z\"");
    CHECK(where(unknown_key).rfind("t.jsonl: line 1, /steps/", 0) == 0);
    CHECK(where(std::string(max_trace_file_bytes + 1, ' ')) == "t.jsonl: ");
}

TEST_CASE("a damaged trace is read or refused as a bad input, never anything else", "[trace][read]") {
    const Scene scene = load_scene_file(PROMYK_SOURCE_DIR "/lessons/scenes/everything.json");
    const std::string good = json_of(trace_pixel(scene, 8, 5, 6, RealType::quad_, Formula::stable, 4));
    std::mt19937 rng(16);
    const std::string alphabet = "0123456789-+.eE[]{},:\"nultrfa \\x";
    int refused = 0;
    const int damaged = sweep_size(3000, 300);
    for (int n = 0; n < damaged; ++n) {
        std::string text = good;
        for (int k = 1 + static_cast<int>(rng() % 3); k > 0; --k) {
            const std::size_t at = rng() % text.size();
            switch (rng() % 3) {
                case 0: text[at] = alphabet[rng() % alphabet.size()]; break;
                case 1: text.erase(at, 1 + rng() % 8); break;
                default: text.insert(at, 1, alphabet[rng() % alphabet.size()]);
            }
        }
        try {
            const PixelTrace trace = read_trace_json(text, "(test)");
            json_of(trace);  // what is read can be written
        } catch (const InputError&) {
            ++refused;
        }
    }
    CHECK(refused > damaged / 3);
}
