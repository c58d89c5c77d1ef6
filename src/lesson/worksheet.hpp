// Worksheets: a lesson printed with numbered blanks where the pixels' numbers
// go, for students to fill in by hand (`promyk lesson NAME --worksheet`), and
// the teacher's answer key (`--key`). The scene's values (S, r, L, ...) stay
// filled in: they are given. lessons/README.md describes what a worksheet shows.
#pragma once

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "lesson/lesson_render.hpp"

namespace promyk {

// One blank: which pixel's which value (a component of it, or the whole).
struct WorksheetBlank {
    int number = 0;  // 1, 2, ... in the order the worksheet first shows them
    int i = 0, j = 0;
    std::string key;     // a path, with its settings qualifier when it has one ("delta@float")
    char component = 0;  // 'x', 'y', 'z' or 0
    StepValue value;
    std::vector<std::string> real_text;  // the value's exact text in a non-double type (lesson_render.hpp)
    std::string real = "double";
};

class Worksheet {
public:
    // Turns `view` into a worksheet: from now on each pixel value it renders
    // is a numbered blank (the same value shown twice keeps its number). The
    // view keeps a pointer to this object: it must outlive the rendering.
    explicit Worksheet(LessonView& view);
    Worksheet(const Worksheet&) = delete;
    Worksheet& operator=(const Worksheet&) = delete;

    // A paragraph for under the title: what to do and how to check the numbers.
    std::string intro() const;

    // For the student: an answer file to copy and fill in (`key = ` lines
    // under a [i,j] heading per pixel, each with its blank's number), which
    // `promyk lesson NAME --answers FILE` checks.
    std::string answer_template() const;

    // The answer key: every blank shown so far with its value.
    std::string answer_key() const;

    const std::vector<WorksheetBlank>& blanks() const { return blanks_; }

    // The blank's text: "..........(3)" for a number, "(......; ......; ......)(4)"
    // for a point (square brackets for a vector; commas in English).
    static std::string blank_text(int number, const std::string& kind, Language language);

private:
    std::string blank_for(const PixelTrace& trace, const std::string& key, char component);

    LessonView& view_;
    std::vector<WorksheetBlank> blanks_;
    // (i, j, key, component) -> the blank's index in blanks_: a lesson of
    // 10^5 pixels has 10^5 blanks, too many to search one by one.
    std::map<std::tuple<int, int, std::string, char>, std::size_t> index_;
};

}  // namespace promyk
