// The bench's tables: columns as wide as their widest cell or heading line,
// counted in display columns, headings bottom-aligned.
#include <catch2/catch.hpp>

#include "util/text_table.hpp"

using promyk::TextColumn;
using promyk::TextTable;

TEST_CASE("a text table aligns names left, numbers right, and headings at the bottom", "[text_table]") {
    TextTable table({{"scene", true}, {"ns/pixel"}, {"shadow rays\na pixel"}});
    table.add_row({"article", "7.55", "0.000"});
    table.add_break();
    table.add_row({"two_spheres", "19.32", "1.5"});
    CHECK(table.text() ==
          "                         shadow rays\n"
          "  scene        ns/pixel      a pixel\n"
          "  article          7.55        0.000\n"
          "\n"
          "  two_spheres     19.32          1.5\n");
}

TEST_CASE("a text table counts a character as one column, whatever its bytes", "[text_table]") {
    // "ł", "≠" and "×" take two or three bytes each and one column.
    TextTable table({{"gałąź ≠"}, {"× baza", true}}, 0, 1);
    table.add_row({"1", "ąę"});
    CHECK(table.text() ==
          "gałąź ≠ × baza\n"
          "      1 ąę\n");
}
