// Sizes in messages (the trace limit, the page's embedded traces): the
// digits a reader is shown, at every unit boundary, in both languages.
#include <catch2/catch.hpp>

#include "trace/byte_size_text.hpp"
#include "trace/messages.hpp"

using namespace promyk;

TEST_CASE("byte_size_text: one decimal below 100 of a unit, none above, never 1000 of a unit", "[messages]") {
    const Language before = ui_language();
    set_ui_language(Language::en);
    CHECK(byte_size_text(0) == "0 B");
    CHECK(byte_size_text(812) == "812 B");
    CHECK(byte_size_text(999.4) == "999 B");
    CHECK(byte_size_text(999.5) == "1.0 kB");
    CHECK(byte_size_text(5300) == "5.3 kB");
    CHECK(byte_size_text(99949) == "99.9 kB");
    CHECK(byte_size_text(99950) == "100 kB");
    CHECK(byte_size_text(739e3) == "739 kB");
    CHECK(byte_size_text(999499) == "999 kB");
    CHECK(byte_size_text(999500) == "1.0 MB");
    CHECK(byte_size_text(17.8e6) == "17.8 MB");
    CHECK(byte_size_text(250e6) == "250 MB");
    CHECK(byte_size_text(4.19e9) == "4.2 GB");
    CHECK(byte_size_text(3e21) == "3000 EB");
    set_ui_language(Language::pl);
    CHECK(byte_size_text(17.8e6) == "17,8 MB");
    CHECK(byte_size_text(250e6) == "250 MB");
    set_ui_language(before);
}
