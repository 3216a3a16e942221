// Area-weighted histogram of a piecewise-linear field: bin k holds the exact area of the
// surface where the interpolated value lies in it, from the closed-form distribution of
// each linear patch, so the bars agree with the clipped tolerance areas.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "geometry/linear_patch.hpp"
#include "statistics/value_range.hpp"

namespace ncv {

struct HistogramOptions {
  std::uint32_t bins = 64;
  std::optional<ValueRange> range;  // default: [d_min, d_max] of the data
};

// Bin 0 is [lo, edge 1], bin k > 0 is (edge k, edge k+1]: the area at a value equal to an
// edge goes to the lower bin, matching area_at_most.
struct Histogram {
  ValueRange range;
  std::vector<double> area;  // per bin
  double below_range = 0;    // area with values < range.lo
  double above_range = 0;    // area with values > range.hi
  double total_area = 0;     // of all patches, inside the range or not

  std::size_t bin_count() const { return area.size(); }
  double edge(std::size_t k) const;
};

// A degenerate range (lo == hi) gets a single bin. Throws UsageError for zero bins or a
// range that is not finite and ordered.
Histogram area_histogram(std::span<const LinearPatch> patches, ValueRange range,
                         std::uint32_t bins);

// area_histogram in pieces, for a pass over the patches shared with other measures: the sums
// of each block of patches (in the blocks area_histogram uses, kHistogramBlock patches),
// combined in block order, give area_histogram's histogram to the bit.
inline constexpr std::size_t kHistogramBlock = std::size_t{1} << 16;
class HistogramSums {
 public:
  HistogramSums(ValueRange range, std::uint32_t bins);  // throws as area_histogram
  std::vector<double> zero() const;
  std::vector<double> block(std::span<const LinearPatch> patches) const;
  static void combine(std::vector<double>& acc, const std::vector<double>& part);
  Histogram histogram(const std::vector<double>& sums) const;

 private:
  Histogram empty_;
  std::vector<double> edges_;
};

}  // namespace ncv
