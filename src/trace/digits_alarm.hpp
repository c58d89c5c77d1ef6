// When lost digits deserve the ⚠ mark and the advice to try another formula.
//
// Every step that can cancel carries its digits lost (digits_lost.hpp), and
// the text trace shows the count from 3 digits up. Losing 3 of a double's 16
// digits is harmless, so the mark and the advice are kept for steps where
//
//   1. fewer than half of the type's digits survive: digits_lost > full / 2
//      (float 3.6, double 8.0, long double 9.6, quad 17.0), or
//   2. the error the loss allows can change the pixel's grey level: the
//      step's relative error, about 10^(digits_lost − full) (the operands'
//      rounding, a unit in the last place, magnified by the cancellation),
//      carried to I_P relatively (to first order every later step scales
//      it), moves 255·I_P across a rounding boundary of the grey level.
//
// A loss that could change the branch (a wrong sign of Δ/4 or D) loses every
// digit, so rule 1 covers it. The text trace and the web page both call this
// function, so they mark the same steps.
#pragma once

#include <string_view>
#include <vector>

namespace promyk {

// The full digits of a real type named as traces name it ("float",
// "double", "long-double", "quad"): p·log10(2); 0 for an unknown name.
double full_digits_of(std::string_view real);

// `intensities`: the pixel's result, one value for a grey scene or one a
// channel, when its value follows from the steps (a lit or shadowed pixel);
// empty when the result is a constant of the branch (background, dark).
bool digits_lost_alarm(double digits_lost, double full_digits, const std::vector<double>& intensities);

}  // namespace promyk
