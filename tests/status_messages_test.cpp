// Errors and status lines in the run's language (lessons/messages_status.json):
// with Polish chosen, what a user reads is Polish, with no English words
// left in it; the English wording is today's; every message fits 80 columns
// after "promyk: ".
#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/timing.hpp"
#include "lesson/lesson_library.hpp"
#include "render/kernel.hpp"
#include "render/tracer.hpp"
#include "temp_dir.hpp"
#include "trace/messages.hpp"
#include "util/errors.hpp"
#include "util/output_file.hpp"

using namespace promyk;

namespace {

// Sets the run's language for one test, and puts the previous one back.
struct LanguageForTest {
    Language previous = ui_language();
    explicit LanguageForTest(Language language) { set_ui_language(language); }
    ~LanguageForTest() { set_ui_language(previous); }
};

template <class Error, class F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const Error& error) {
        return error.what();
    }
    FAIL("no error thrown");
    return "";
}

// The words of a text, lower case (ASCII letters only: English words).
bool has_word(const std::string& text, const std::string& word) {
    return std::regex_search(text, std::regex("(^|[^A-Za-z])" + word + "($|[^A-Za-z])", std::regex::icase));
}

// English words that a Polish message must not contain.
const std::vector<std::string> status_english = {"cannot", "write", "read", "no", "such", "file", "directory", "the",
                                          "is",     "not",   "square", "samples", "and", "exactly", "one", "sphere",
                                          "repetitions", "took", "under", "scene", "header", "same", "standard",
                                          "output", "of"};

void check_polish(const std::string& text) {
    CAPTURE(text);
    for (const std::string& word : status_english) {
        CAPTURE(word);
        CHECK_FALSE(has_word(text, word));
    }
}

// Display width: code points.
std::size_t width(const std::string& text) {
    std::size_t n = 0;
    for (const unsigned char c : text) n += (c & 0xC0) != 0x80;
    return n;
}

}  // namespace

TEST_CASE("output errors in Polish: an unwritable path, a directory, two outputs that are one file",
          "[messages][status]") {
    const LanguageForTest polish(Language::pl);
    const testing::TempDir dir;
    const std::string path = dir.file("brak/x.png");  // a folder that does not exist
    const std::string missing = error_of<OutputError>([&] { OutputFile out(path); });
    CHECK(missing == "nie można zapisać " + path + ": nie ma takiego pliku ani katalogu");
    check_polish(missing.substr(0, missing.find(path)) + missing.substr(missing.find(path) + path.size()));

    const std::string folder = dir.path.string();
    const std::string is_dir = error_of<OutputError>([&] { inspect_output(folder); });
    CHECK(is_dir == "nie można zapisać " + folder + ": to jest katalog");

    const std::string same = error_of<UsageError>(
        [&] { require_distinct_outputs({{"-o", inspect_output("-")}, {"--traces", inspect_output("-")}}); });
    CHECK(same == "-o i --traces wskazują ten sam plik (standardowe wyjście)");
    check_polish(same);
}

TEST_CASE("the same errors in English are worded as before", "[messages][status]") {
    const LanguageForTest english_run(Language::en);
    const testing::TempDir dir;
    const std::string path = dir.file("missing/x.png");
    CHECK(error_of<OutputError>([&] { OutputFile out(path); }) ==
          "cannot write " + path + ": No such file or directory");
    CHECK(error_of<UsageError>([&] {
              require_distinct_outputs({{"-o", inspect_output("-")}, {"--traces", inspect_output("-")}});
          }) == "-o and --traces name the same file (standard output)");
}

TEST_CASE("render, lesson library and bench messages in Polish", "[messages][status]") {
    const LanguageForTest polish(Language::pl);

    const std::string spp = error_of<UsageError>([] { make_kernel(article_scene(), RealType::double_, Formula::article, 3); });
    CHECK(spp == "liczba próbek na piksel musi być kwadratem (1, 4, ... 1024), a nie 3");
    check_polish(spp);

    Scene two = article_scene();
    two.spheres.push_back(two.spheres.front());
    const std::string spheres = error_of<InputError>([&] { article_world(two); });
    CHECK(spheres == "ta wersja obsługuje tylko jedną kulę (tę z artykułu), a scena ma 2");
    check_polish(spheres);

    const std::string scene = error_of<InputError>([] { LessonLibrary().scene("nieznana"); });
    CHECK(scene == "nie ma takiej sceny w lessons/scenes/ (wskazuje ją nagłówek lekcji)");
    check_polish(scene);

    // A job that never takes long enough: the bench says why in Polish.
    double now = 0;
    bench::TimingPolicy policy;
    policy.clock = [&now] { return now; };
    policy.max_count = 64;
    policy.rounds = 1;
    const std::vector<bench::Timing> t = bench::time_side_by_side({[](long) {}}, policy);
    REQUIRE_FALSE(t[0].timed);
    CHECK(t[0].problem == "64 powtórzeń wciąż trwało krócej niż 20 ms");
    check_polish(t[0].problem);
}

TEST_CASE("every status message fits 80 columns after 'promyk: ', in both languages, errors on one line",
          "[messages][status]") {
    std::ifstream file(PROMYK_SOURCE_DIR "/lessons/messages_status.json");
    REQUIRE(file);
    const nlohmann::json messages = nlohmann::json::parse(file);
    for (const char* language : {"pl", "en"}) {
        REQUIRE(messages[language].size() == messages["en"].size());
        for (const auto& [id, value] : messages[language].items()) {
            if (id == "progress_line") continue;  // not after "promyk: ", and its {what} is the caller's
            // Each argument as four columns: a number, a short name (a path can make any line long).
            const std::string text =
                std::regex_replace(value.get<std::string>(), std::regex("\\{[a-z_]+\\}"), "1024");
            std::size_t start = 0;
            for (int line = 0; start <= text.size(); ++line) {
                const std::size_t end = std::min(text.find('\n', start), text.size());
                const std::string shown = (line == 0 ? "promyk: " : "") + text.substr(start, end - start);
                CAPTURE(language, id, shown);
                CHECK(width(shown) <= 80);
                // A continuation is indented, and only in a line the bench prints itself (an
                // error goes through main's printable(), which would show \\n).
                if (line > 0) CHECK(shown.rfind("  ", 0) == 0);
                if (line > 0) CHECK(id == "bench_accuracy_untimed_row");
                start = end + 1;
            }
        }
    }
}
