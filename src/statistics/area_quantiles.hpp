// Area-weighted quantiles of a piecewise-linear field, exact for the interpolant: the
// q-quantile is the smallest t whose sublevel set {d <= t} covers the fraction q of the
// area (the same distribution the histogram and the tolerance areas use).
#pragma once

#include <span>
#include <vector>

#include "geometry/linear_patch.hpp"

namespace ncv {

// fractions in [0, 1]. values must hold every corner value of the patches, in any order
// (duplicates allowed): the distribution function is quadratic between consecutive corner
// values, which is what makes the search finish in closed form.
// The result is NaN for every fraction when the patches have no area.
std::vector<double> area_quantiles(std::span<const LinearPatch> patches,
                                   std::span<const double> values,
                                   std::span<const double> fractions);

}  // namespace ncv
