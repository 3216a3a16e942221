#include "area_histogram.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "error.hpp"
#include "ordered_reduce.hpp"

namespace ncv {

namespace {

constexpr std::size_t kPatchBlock = 1 << 16;

// Per-block accumulator: the bins, then below_range, above_range and the total area.
using BinSums = std::vector<double>;

// The bin holding value v of [edges.front(), edges.back()].
std::size_t bin_of(const std::vector<double>& edges, double v) {
  const auto first_not_below = std::lower_bound(edges.begin(), edges.end(), v);
  const std::size_t j = static_cast<std::size_t>(first_not_below - edges.begin());
  return j == 0 ? 0 : std::min(j - 1, edges.size() - 2);
}

// Walks the bins the patch spans, giving each the growth of the patch's distribution
// function across it.
void add_patch(BinSums& sums, const std::vector<double>& edges, const LinearPatch& p) {
  const std::size_t bins = edges.size() - 1;
  double& below = sums[bins];
  double& above = sums[bins + 1];
  sums[bins + 2] += p.area;
  if (p.hi < edges.front()) {
    below += p.area;
    return;
  }
  if (p.lo > edges.back()) {
    above += p.area;
    return;
  }
  const std::size_t first = bin_of(edges, std::max(p.lo, edges.front()));
  const std::size_t last = bin_of(edges, std::min(p.hi, edges.back()));
  if (first == last && p.lo >= edges.front() && p.hi <= edges.back()) {
    sums[first] += p.area;
    return;
  }
  double done = area_below(p, edges.front());
  below += done;
  for (std::size_t k = first; k < last; ++k) {
    const double upto = area_at_most(p, edges[k + 1]);
    sums[k] += upto - done;
    done = upto;
  }
  const double upto = area_at_most(p, edges.back());
  sums[last] += upto - done;
  above += p.area - upto;
}

}  // namespace

double Histogram::edge(std::size_t k) const {
  return std::lerp(range.lo, range.hi, static_cast<double>(k) / static_cast<double>(bin_count()));
}

Histogram area_histogram(std::span<const LinearPatch> patches, ValueRange range,
                         std::uint32_t bins) {
  if (bins == 0) throw UsageError("a histogram needs at least one bin");
  if (!std::isfinite(range.lo) || !std::isfinite(range.hi) || range.lo > range.hi) {
    throw UsageError(
        fmt::format("histogram range {}:{} is not a finite interval", range.lo, range.hi));
  }
  Histogram histogram;
  histogram.range = range;
  histogram.area.resize(range.lo == range.hi ? 1 : bins);
  const std::size_t count = histogram.bin_count();
  std::vector<double> edges(count + 1);
  for (std::size_t k = 0; k <= count; ++k) edges[k] = histogram.edge(k);

  BinSums sums = ordered_reduce(
      patches.size(), kPatchBlock, BinSums(count + 3, 0.0),
      [&](std::size_t begin, std::size_t end) {
        BinSums part(count + 3, 0.0);
        for (std::size_t i = begin; i < end; ++i) add_patch(part, edges, patches[i]);
        return part;
      },
      [](BinSums& acc, const BinSums& part) {
        for (std::size_t k = 0; k < acc.size(); ++k) acc[k] += part[k];
      });
  std::copy_n(sums.begin(), count, histogram.area.begin());
  histogram.below_range = sums[count];
  histogram.above_range = sums[count + 1];
  histogram.total_area = sums[count + 2];
  return histogram;
}

}  // namespace ncv
