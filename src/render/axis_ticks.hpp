// "Nice" tick values for a numeric axis: multiples of 1, 2 or 5 times a power of ten.
#pragma once

#include <vector>

namespace ncv {

// About `wanted` ticks within [lo, hi], ascending. Each value is an integer divided (or
// multiplied) by an exact power of ten, so it prints as the short decimal it stands for
// ("0.3", not "0.30000000000000004"). A degenerate interval gets the one value.
std::vector<double> axis_ticks(double lo, double hi, int wanted);

}  // namespace ncv
