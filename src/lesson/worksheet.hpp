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

    // The answer file's lines alone (what answer_template() shows under its
    // heading, without the indent): a [i,j] heading per pixel, then
    // "key = VALUE  # (N) symbol" per blank in derivation order, VALUE the
    // text `typed` holds for blank N (none: blank). What the web page saves
    // and checks; `promyk lesson NAME --answers FILE` reads it.
    std::string answer_lines(const std::map<int, std::string>& typed = {}) const;

    // The command that checks the answer file, on one line.
    std::string check_command() const;

    // HTML (LessonFormat::html): a rendered step with its blanks' marks made
    // fields, one <input> a blank with its <label> (the first place the
    // blank shows; a later place shows its number alone); other formats
    // unchanged.
    std::string fields(const std::string& rendered);

    const std::vector<WorksheetBlank>& blanks() const { return blanks_; }

    // The blank's text: "..........(3)" for a number, "(......; ......; ......)(4)"
    // for a point (square brackets for a vector; commas in English).
    static std::string blank_text(int number, const std::string& kind, Language language);

private:
    std::string form_lines(const std::map<int, std::string>& typed, std::size_t indent) const;
    std::string field(const WorksheetBlank& blank, bool first) const;
    std::string blank_for(const PixelTrace& trace, const std::string& key, char component);

    LessonView& view_;
    std::vector<WorksheetBlank> blanks_;
    // (i, j, key, component) -> the blank's index in blanks_: a lesson of
    // 10^5 pixels has 10^5 blanks, too many to search one by one.
    std::map<std::tuple<int, int, std::string, char>, std::size_t> index_;
    std::vector<bool> has_field_;  // by blank: its <input> is out (HTML)
};

}  // namespace promyk
