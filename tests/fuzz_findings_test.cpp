// What the fuzzers (tests/fuzz) found, each as the property it broke; the
// inputs themselves are in tests/fuzz/corpus/ (fuzz.corpus.* replays them).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "lesson/lesson.hpp"

using namespace promyk;

// fuzz_lesson: "## \n= " threw std::out_of_range (exit 70): the table's
// line trimmed to "=" and its keys were read from past its end.
TEST_CASE("a value table line with no keys is read as an empty table, wherever it stands", "[fuzz][lesson]") {
    const std::string header = "---\nname: x\ntitle: T\nsummary: S\n---\n## [a] A\n\n";
    for (const std::string table : {"= ", "=  ", "= \t", "= \r"})
        for (const std::string after : {"", "\n", "\nprose\n"}) {
            std::vector<LessonProblem> problems;
            const Lesson lesson = parse_lesson(header + table + after, "x.md", Language::en, problems);
            REQUIRE(lesson.steps.size() == 1);
            REQUIRE(!lesson.steps[0].parts.empty());
            CHECK(lesson.steps[0].parts[0].kind == PartKind::values);
            CHECK(lesson.steps[0].parts[0].keys.empty());
        }
    std::vector<LessonProblem> problems;
    CHECK_NOTHROW(parse_lesson("## \n= ", "x.md", Language::en, problems));
    const Lesson two = parse_lesson(header + "= t  delta \n", "x.md", Language::en, problems);
    CHECK(two.steps.at(0).parts.at(0).keys == std::vector<std::string>{"t", "delta"});
}
