// Text from outside (file contents, keys, file names) made safe to print on a
// terminal: nothing in it can move the cursor, change colours, end a line,
// reorder the text around it or hide what follows.
#pragma once

#include <string>
#include <string_view>

namespace promyk {

// `text` with every character that a terminal would act on, or that hides or
// reorders text, written as a visible escape; everything else unchanged.
//
//   - C0 controls U+0000–U+001F: newline, carriage return and tab as "\n",
//     "\r", "\t"; the others as "\u001b" (four lower-case hex digits);
//   - DEL U+007F and the C1 controls U+0080–U+009F: "\u007f", "\u0085", ...;
//   - the characters that reorder or hide text without being seen: the
//     bidirectional controls (U+061C, U+200E, U+200F, U+202A–U+202E,
//     U+2066–U+2069), the line and paragraph separators U+2028, U+2029 and
//     the byte order mark U+FEFF: "\u202e", ...;
//   - a byte that is not part of valid UTF-8 (a stray continuation byte, a
//     truncated sequence, an overlong form, a surrogate, above U+10FFFF):
//     "\xff" (two lower-case hex digits), one escape per byte.
//
// Backslashes are left as they are, and valid printable UTF-8 (Polish
// letters, "²", "−", emoji) is kept. The result is valid UTF-8 that contains
// none of the characters above, so printable(printable(t)) == printable(t):
// applying it again (to a whole message at print time) changes nothing.
std::string printable(std::string_view text);

}  // namespace promyk
