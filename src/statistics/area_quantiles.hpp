// Area-weighted quantiles of a piecewise-linear field, exact for the interpolant: the
// q-quantile is the smallest t whose sublevel set {d <= t} covers the fraction q of the
// area (the same distribution the histogram and the tolerance areas use).
#pragma once

#include <span>
#include <vector>

#include "geometry/patch_source.hpp"
#include "statistics/patch_passes.hpp"

namespace ncv {

// fractions in [0, 1]. values must hold every corner value of the patches, in any order
// (duplicates allowed): the distribution function is quadratic between consecutive corner
// values, which is what makes the search finish in closed form.
// The result is NaN for every fraction when the patches have no area.
std::vector<double> area_quantiles(const PatchSource& patches, std::span<const double> values,
                                   std::span<const double> fractions);

// area_quantiles in pieces, for a pass over the patches shared with other measures: the first
// step's split points come from the values alone, its sums over each block of patches (in
// the blocks of statistics/patch_passes.hpp, kPatchBlock patches) combined in block order
// are area_quantiles' own to the bit, and the search goes on from them with further passes
// over `patches`.
class AreaQuantiles {
 public:
  explicit AreaQuantiles(std::span<const double> values);  // kept by reference
  std::vector<double> zero() const;
  std::vector<double> block(std::span<const LinearPatch> patches) const;
  static void combine(std::vector<double>& acc, const std::vector<double>& part);
  // `along`, when set, sees every patch once, in index order, on one thread, before this
  // returns: it rides on one of the search's serial passes (the one with fewer brackets),
  // or has a pass of its own beside them when there is no such pass.
  std::vector<double> quantiles(const PatchSource& patches, std::span<const double> fractions,
                                const std::vector<double>& sums,
                                const PatchRangeVisitor& along = {}) const;

 private:
  std::span<const double> values_;
  std::vector<double> splits_;
};

}  // namespace ncv
