// The web page template, embedded in promyk at build time (web_export/):
// one HTML file holding the page's code, its styles and fonts, three.js,
// KaTeX and the tracer compiled to WebAssembly. `promyk export` puts a
// scene's data into it at web_page_data_marker.
#pragma once

#include <string_view>

namespace promyk::app {

// The template; empty when this promyk was built without the web page.
std::string_view web_page_template();
// What the build lacked to make the page ("em++ (emscripten), npm"); empty
// when the template is there.
std::string_view web_page_missing();

// Where the data goes: the only occurrence of this text in the template,
// inside <script type="application/json">.
inline constexpr std::string_view web_page_data_marker = "@PROMYK_EXPORT_DATA@";

}  // namespace promyk::app
