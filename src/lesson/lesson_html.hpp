// HTML for the lesson runner's html output (lesson_render.hpp) and the web
// page: every text from a lesson or a scene escaped; formulas left as TeX in
// <span class="math"> (the page typesets them with KaTeX, trust: false).
#pragma once

#include <string>
#include <string_view>

namespace promyk {

// & < > " ' as entities: safe in element text and in quoted attributes.
std::string html_escape(std::string_view text);

// TeX in an element the page typesets: <span class="math">TEX</span>, the TeX escaped.
std::string html_math(std::string_view tex);

// One line of lesson Markdown inline: `code`, **bold**, *emphasis*, $TeX$;
// everything else escaped. A marker without its closing twin is a character.
std::string html_inline(std::string_view text);

// Lesson prose (the Markdown lessons/README.md describes: paragraphs, lists,
// fenced and indented code, tables, # headings) as HTML blocks.
std::string html_prose(std::string_view text);

}  // namespace promyk
