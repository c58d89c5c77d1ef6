// The trace note's example in the trace's own real type: a number of the
// scene that the type cannot hold exactly (the first given number that
// reads as a short decimal and is not a binary fraction: the article's z_S
// = 3.2), as that type stores it, and its square computed in that type,
// beside the decimal square the reader expects. A scene number is read as a
// double and then converted, as every scene number is; the note under a
// float trace speaks of float's value, not double's.
#pragma once

#include <string>
#include <vector>

namespace promyk {

struct TypeExample {
    std::string type;          // as the note names it: float, double, long double, quad
    std::string number;        // the number as the scene gives it, shortest decimal: "3.2"
    std::string stored;        // the number as the type holds it, its first 20 significant digits
    bool cut = false;          // whether stored leaves digits out (the note then adds "…")
    std::string square;        // the number times itself in the type: the shortest text that reads back to it
    std::string exact_square;  // the decimal number times itself, exactly: "10.24"
};

// `real` is a trace's numeric.real: "float", "double", "long-double" or "quad"
// (anything else is taken as double). `given`: the scene's numbers in the
// order the trace header gives them; the first positive or negative one
// between 0.01 and 10000, of at most 6 significant digits, that the type
// does not hold exactly, and whose square in the type does not print as the
// decimal square, is the example (its magnitude); 3.2 if none is.
TypeExample type_example(const std::string& real, const std::vector<double>& given = {});

}  // namespace promyk
