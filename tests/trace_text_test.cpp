// The text trace as a class reads it: branch names in the run's language
// (no English word in Polish output), a colour labelled as a colour, the
// digits rule (--digits), the note on cos α above 1, and trace --compare's
// agreement and closing lines, and the closing note's example in the trace's own type.
#include <catch2/catch.hpp>

#include <array>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "render/trace_pixel.hpp"
#include "scene/scene.hpp"
#include "trace/intensity_formula.hpp"
#include "trace/messages.hpp"
#include "trace/trace_compare.hpp"
#include "trace/trace_text.hpp"
#include "trace/type_example.hpp"
#include "trace/vocabulary.hpp"
#include "flat_text.hpp"

using namespace promyk;

namespace {

std::string text_of(const PixelTrace& trace, Language language, int digits = 0) {
    TraceTextOptions options;
    options.language = language;
    options.digits = digits;
    return format_trace_text(trace, builtin_vocabulary(), options);
}

std::string fmt_rgb(const std::array<int, 3>& rgb) {
    return "[" + std::to_string(rgb[0]) + ", " + std::to_string(rgb[1]) + ", " + std::to_string(rgb[2]) + "]";
}

Scene coloured_scene() {
    Scene scene = article_scene();
    scene.materials.push_back(Material{0, 1, 0, 10, Colour{1, 0.5, 0.25}});
    scene.spheres[0].material = 0;
    return scene;
}

}  // namespace

TEST_CASE("trace text: branch names in the run's language", "[trace-text]") {
    // At w = 8: (0, 0) misses, (5, 1) is on the dark side, (3, 4) is lit.
    const std::vector<std::pair<int, int>> pixels = {{0, 0}, {5, 1}, {3, 4}};
    const std::vector<std::string> polish = {"gałąź: chybienie — ", "gałąź: ciemna strona — ", "gałąź: strona oświetlona — "};
    const std::vector<std::string> english = {"branch: miss — ", "branch: dark side — ", "branch: lit side — "};
    for (std::size_t k = 0; k < pixels.size(); ++k) {
        const PixelTrace trace = trace_pixel(article_scene(), 8, pixels[k].first, pixels[k].second);
        const std::string pl = text_of(trace, Language::pl), en = text_of(trace, Language::en);
        CHECK(pl.find(polish[k]) != std::string::npos);
        CHECK(en.find(english[k]) != std::string::npos);
        // English words of the branch names and the scene's fields never in Polish.
        for (const char* word : {"background", "lit", "miss", "dark", "branch", "grey level"}) {
            INFO(word << " in\n" << pl);
            CHECK(pl.find(std::string(" ") + word) == std::string::npos);
        }
        CHECK(pl.find("tło = 0,5") != std::string::npos);
    }
}

TEST_CASE("trace text: a colour is called a colour, with one kind of bracket", "[trace-text]") {
    const PixelTrace trace = trace_pixel(coloured_scene(), 8, 3, 4);
    REQUIRE(trace.result_rgb);
    const std::string en = text_of(trace, Language::en);
    CHECK(en.find("grey level") == std::string::npos);
    CHECK(en.find(fmt_rgb(trace.rgb)) != std::string::npos);
    CHECK(en.find("colour: [") != std::string::npos);
    CHECK(text_of(trace, Language::pl).find("kolor: [") != std::string::npos);
}

TEST_CASE("trace text: --digits rounds every value shown, the default shows every digit", "[trace-text]") {
    const PixelTrace trace = trace_pixel(article_scene(), 8, 3, 4);
    const std::string all = text_of(trace, Language::en), four = text_of(trace, Language::en, 4);
    CHECK(all.find("= 4.557812500000004\n") != std::string::npos);
    CHECK(four.find("= 4.558\n") != std::string::npos);
    CHECK(four.find("= 10.24\n") != std::string::npos);        // |S|² = 10.240000000000002
    CHECK(four.find("I_P = I·D / (r·√|K|²) = 0.6957") != std::string::npos);
    CHECK(four.find("4.557812500000004") == std::string::npos);
    CHECK(text_of(trace, Language::pl, 4).find("= 4,558\n") != std::string::npos);
    // negatives carry the minus sign U+2212 in both languages, as formulas do
    CHECK(all.find("−1.083983078994792]") != std::string::npos);
    CHECK(all.find("-1.08") == std::string::npos);
}

// A ray that just misses a far sphere "hits" it in double once Δ/4 loses
// every digit: the hit lies beside the sphere and cos α comes out 10298.
TEST_CASE("trace text: cos α above 1 is said to mean the hit is not on the sphere", "[trace-text]") {
    Scene scene = article_scene();
    scene.z_E = 1.0 / 128;
    scene.spheres[0].S = Vec3d{1257558701527, 1257558701527, 5030234806090};
    scene.spheres[0].r = 6;
    const PixelTrace trace = trace_pixel(scene, 512, 255, 256);
    const std::string en = flat(text_of(trace, Language::en)), pl = flat(text_of(trace, Language::pl));
    INFO(en);
    CHECK(en.find("cos α = 1.030e+04 > 1") != std::string::npos);
    CHECK(en.find("this \"hit\" is not on the sphere") != std::string::npos);
    CHECK(pl.find("cos α = 1,030e+04 > 1") != std::string::npos);
    // the article's pixel: no such note
    CHECK(text_of(trace_pixel(article_scene(), 8, 3, 4), Language::en).find("A cosine never exceeds 1") == std::string::npos);
}

TEST_CASE("trace --compare: a vector agrees as far as its worst component, and the results close it", "[trace-text]") {
    std::vector<PixelTrace> traces;
    for (const RealType type : {RealType::float_, RealType::double_, RealType::quad_})
        traces.push_back(trace_pixel(article_scene(), 8, 3, 4, type));
    const std::string en = format_comparison(traces, builtin_vocabulary(), Language::en);
    INFO(en);
    // E = (0.125, 0.125, 2) is exact in every type: every component equal.
    CHECK(en.find("(0.125, 0.125, 2)   exactly equal") != std::string::npos);
    // P in double: no component is exactly quad's, so it is not "exactly equal".
    const std::size_t P = en.find("\nP  P\n");
    REQUIRE(P != std::string::npos);
    const std::string P_rows = en.substr(P, en.find("\n\n", P + 1) - P);
    CHECK(P_rows.find("exactly equal") == std::string::npos);
    CHECK(P_rows.find("significant digits agree") != std::string::npos);
    // the closing lines: branch, intensity and grey level of each type
    CHECK(en.find("branch: : ") == std::string::npos);
    CHECK(en.find("double  branch: lit side; I_P = 0.6957365143147741; level: 177") != std::string::npos);
    CHECK(en.find("float   branch: lit side; I_P = ") != std::string::npos);
    const std::string pl = format_comparison(traces, builtin_vocabulary(), Language::pl);
    CHECK(pl.find("gałąź: strona oświetlona; I_P = 0,6957365143147741; poziom: 177") != std::string::npos);
    for (const std::string& out : {en, pl}) {
        std::size_t start = 0;
        while (start < out.size()) {
            const std::size_t end = std::min(out.find('\n', start), out.size());
            std::size_t width = 0;
            for (std::size_t k = start; k < end; ++k) width += (static_cast<unsigned char>(out[k]) & 0xC0) != 0x80;
            INFO(out.substr(start, end - start));
            CHECK(width <= 80);
            start = end + 1;
        }
    }
}

TEST_CASE("trace text: the branch line names the branch once, then says why", "[trace-text]") {
    // Every branch's words, in both languages and every effect set, never
    // repeat its short name ("lit side — the lit side (D > 0)" was the fault).
    const Vocabulary& vocabulary = builtin_vocabulary();
    const Branch branches[] = {Branch::miss, Branch::dark, Branch::lit, Branch::shadowed, Branch::non_finite};
    for (const Language language : {Language::pl, Language::en})
        for (const Branch branch : branches)
            for (const char* effects : {"lambert", "lights+shadows+phong+colour"}) {
                const std::string name = message(language, "branch_name_" + std::string(branch_name(branch)));
                const std::string about = branch_about(vocabulary, branch, effects, language);
                INFO(name << " / " << about);
                CHECK(!about.empty());
                std::string lower_about = about;
                for (char& c : lower_about) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
                CHECK(lower_about.find(name) == std::string::npos);
                CHECK(branch_named(vocabulary, branch, effects, language) == name + " — " + about);
            }
    // The trace's footer is that line, once.
    for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {5, 1}, {3, 4}}) {
        const PixelTrace trace = trace_pixel(article_scene(), 8, i, j);
        for (const Language language : {Language::pl, Language::en}) {
            const std::string text = text_of(trace, language);
            const std::string name = message(language, "branch_name_" + std::string(branch_name(trace.branch)));
            std::size_t count = 0;
            for (std::size_t at = text.find(name); at != std::string::npos; at = text.find(name, at + 1)) ++count;
            INFO(text);
            CHECK(count == 1);
        }
    }
}

TEST_CASE("trace text: the closing note's 3.2 and 3.2² are the trace's own type's", "[trace-text]") {
    // Expected values computed apart from promyk (Python's fractions): 3.2
    // (the double) rounded to the type's significand (24, 53, 64, 113 bits),
    // its first 20 significant digits, and its square rounded in the type, as
    // the shortest decimal that rounds back to it there.
    struct Expected {
        RealType real;
        const char* type;
        const char* stored;
        const char* square;
    };
    const Expected cases[] = {
        {RealType::float_, "float", "3.2000000476837158203", "10.240001"},
        {RealType::double_, "double", "3.2000000000000001776", "10.240000000000002"},
        {RealType::long_double, "long double", "3.2000000000000001776", "10.240000000000001137"},
        {RealType::quad_, "quad", "3.2000000000000001776", "10.240000000000001136868377216160329"},
    };
    for (const Expected& expected : cases) {
        const std::string real(real_type_name(expected.real));
        INFO(real);
        const TypeExample example = type_example(real);
        CHECK(example.type == expected.type);
        CHECK(example.stored == expected.stored);
        CHECK(example.cut);
        CHECK(example.square == expected.square);
        // The note as a trace in that type shows it, in both languages.
        const PixelTrace trace = trace_pixel(article_scene(), 8, 3, 4, expected.real);
        const std::string en = flat(text_of(trace, Language::en));
        const std::string pl = flat(text_of(trace, Language::pl));
        CHECK_THAT(en, Catch::Contains(std::string("reads back as the same ") + expected.type + "."));
        CHECK_THAT(en, Catch::Contains(std::string("stored as ") + expected.stored + "…, so 3.2² gives " +
                                       expected.square + ", not 10.24."));
        CHECK_THAT(pl, Catch::Contains(std::string("tę samą liczbę ") + expected.type + "."));
        CHECK_THAT(pl, Catch::Contains("więc 3,2² daje " + local_number_text(expected.square, Language::pl)));
    }
}

TEST_CASE("trace text: the closing note's example is a number of the trace's own scene", "[trace-text]") {
    // Expected values computed apart from promyk (Python's decimal, 200
    // digits, and struct for float): 1.1 and 0.4 as double and float hold
    // them, their first 20 significant digits, and their squares rounded in
    // the type, as the shortest decimal that reads back to the same value.
    Scene scene = article_scene();
    scene.spheres[0].S = {0, 0, 4};
    scene.spheres[0].r = 1.1;  // z_E = 2 and S come first, and are binary fractions
    std::string en = flat(text_of(trace_pixel(scene, 8, 3, 4), Language::en));
    CHECK_THAT(en, Catch::Contains("1.1 is stored as 1.1000000000000000888…, so 1.1² gives 1.2100000000000002, "
                                   "not 1.21."));
    const std::string pl = flat(text_of(trace_pixel(scene, 8, 3, 4), Language::pl));
    CHECK_THAT(pl, Catch::Contains("1,1 jest przechowywane jako 1,1000000000000000888…, więc 1,1² daje "
                                   "1,2100000000000002, a nie 1,21."));
    // A negative number is taken by its magnitude, in float as float holds it.
    scene.spheres[0].r = 1;
    scene.lights[0].L = {-0.4, 1, 1};
    en = flat(text_of(trace_pixel(scene, 8, 3, 4, RealType::float_), Language::en));
    CHECK_THAT(en, Catch::Contains("0.4 is stored as 0.40000000596046447753…, so 0.4² gives 0.16000001, not 0.16."));
    // 0.3 is no binary fraction, but 0.3² prints as 0.09 in double: it says
    // nothing, and with every other number a binary fraction the note falls
    // back to the article's 3.2.
    scene.lights[0].L = {0.3, 1, 1};
    en = flat(text_of(trace_pixel(scene, 8, 3, 4), Language::en));
    CHECK_THAT(en, Catch::Contains("3.2 is stored as 3.2000000000000001776…, so 3.2² gives 10.240000000000002, "
                                   "not 10.24."));
    CHECK(type_example("double", {0.3}).number == "3.2");
    CHECK(type_example("double", {0.001, 20000.5, 1.2345678}).number == "3.2");  // too small, too big, too long
    const TypeExample small = type_example("double", {std::nan(""), 0.001, -0.07});
    CHECK(small.number == "0.07");
    CHECK(small.stored == "0.070000000000000006661");  // Python: Decimal(0.07), 20 significant digits
    CHECK(small.cut);
    CHECK(small.square == "0.004900000000000001");      // Python: repr(0.07 * 0.07)
    CHECK(small.exact_square == "0.0049");
}
