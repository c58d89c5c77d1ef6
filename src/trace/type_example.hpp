// The trace note's example in the trace's own real type: the article's
// z_S = 3.2 (a scene number, read as a double, as every scene number is)
// as that type stores it, and its square computed in that type, so the
// note under a float trace speaks of float's 3.2, not double's.
#pragma once

#include <string>

namespace promyk {

struct TypeExample {
    std::string type;    // as the note names it: float, double, long double, quad
    std::string stored;  // 3.2 as the type holds it, its first 20 significant digits
    bool cut = false;    // whether stored leaves digits out (the note then adds "…")
    std::string square;  // 3.2 times 3.2 in the type: the shortest text that reads back to it
};

// `real` is a trace's numeric.real: "float", "double", "long-double" or "quad"
// (anything else is taken as double).
TypeExample type_example(const std::string& real);

}  // namespace promyk
