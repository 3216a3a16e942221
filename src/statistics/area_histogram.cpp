#include "statistics/area_histogram.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "util/error.hpp"
#include "util/ordered_reduce.hpp"

namespace ncv {

namespace {

using BinSums = std::vector<double>;  // HistogramSums::zero()

// The bins' edges, and the bin holding a value: bin k holds (edge k, edge k + 1], bin 0
// also its lower edge. The quotient by the bin width guesses the bin; the edges (computed by
// lerp, not exactly lo + k * width) then correct the guess by a step at most, which is
// what a binary search over them would find.
class BinEdges {
 public:
  explicit BinEdges(std::vector<double> edges)
      : edges_(std::move(edges)),
        per_unit_(static_cast<double>(edges_.size() - 1) / (edges_.back() - edges_.front())) {}

  double operator[](std::size_t k) const { return edges_[k]; }
  double front() const { return edges_.front(); }
  double back() const { return edges_.back(); }
  std::size_t bins() const { return edges_.size() - 1; }

  std::size_t bin_of(double v) const {
    const double guess = (v - edges_.front()) * per_unit_;
    const double top = static_cast<double>(bins() - 1);
    // The negated test also sends a NaN quotient (a single-valued range) to bin 0.
    std::size_t k = !(guess > 0) ? 0 : static_cast<std::size_t>(std::min(guess, top));
    while (k > 0 && v <= edges_[k]) --k;
    while (k + 1 < bins() && v > edges_[k + 1]) ++k;
    return k;
  }

 private:
  std::vector<double> edges_;
  double per_unit_;
};

// Walks the bins the patch spans, giving each the growth of the patch's distribution
// function across it. Returns the bin of its largest value (or of the range's end).
std::size_t add_patch(BinSums& sums, const BinEdges& edges, const LinearPatch& p) {
  const std::size_t bins = edges.bins();
  double& below = sums[bins];
  double& above = sums[bins + 1];
  if (p.hi < edges.front()) {
    below += p.area;
    return 0;
  }
  if (p.lo > edges.back()) {
    above += p.area;
    return bins - 1;
  }
  const std::size_t first = edges.bin_of(std::max(p.lo, edges.front()));
  const std::size_t last = edges.bin_of(std::min(p.hi, edges.back()));
  if (first == last && p.lo >= edges.front() && p.hi <= edges.back()) {
    sums[first] += p.area;
    return first;
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
  return last;
}

// One block's bins, into sums at zero. Neighbouring patches mostly fall into the bin of the
// patch before: when one lies inside (edge k, edge k + 1], both bin searches would give k
// and the whole area goes there, which the test does without them. The total and that
// bin's sum are kept in registers, each add the one it was (through memory each waited for
// the store before it).
void add_patches(BinSums& sums, const BinEdges& edges, std::span<const LinearPatch> patches) {
  double total = 0;
  std::size_t bin = 0;
  double in_bin = sums[bin];
  double low = INFINITY, high = -INFINITY;
  for (const LinearPatch& p : patches) {
    total += p.area;
    if (low < p.lo && p.hi <= high) {
      in_bin += p.area;
      continue;
    }
    sums[bin] = in_bin;
    bin = add_patch(sums, edges, p);
    in_bin = sums[bin];
    low = edges[bin];
    high = edges[bin + 1];
  }
  sums[bin] = in_bin;
  sums[edges.bins() + 2] = total;
}

}  // namespace

double Histogram::edge(std::size_t k) const {
  return std::lerp(range.lo, range.hi, static_cast<double>(k) / static_cast<double>(bin_count()));
}

HistogramSums::HistogramSums(ValueRange range, std::uint32_t bins) {
  if (bins == 0) throw UsageError("a histogram needs at least one bin");
  if (!std::isfinite(range.lo) || !std::isfinite(range.hi) || range.lo > range.hi) {
    throw UsageError(
        fmt::format("histogram range {}:{} is not a finite interval", range.lo, range.hi));
  }
  empty_.range = range;
  empty_.area.resize(range.lo == range.hi ? 1 : bins);
  const std::size_t count = empty_.bin_count();
  edges_.resize(count + 1);
  for (std::size_t k = 0; k <= count; ++k) edges_[k] = empty_.edge(k);
}

// Per block: the bins, then below_range, above_range and the total area.
std::vector<double> HistogramSums::zero() const {
  return std::vector<double>(empty_.bin_count() + 3, 0.0);
}

std::vector<double> HistogramSums::block(std::span<const LinearPatch> patches) const {
  // BinEdges keeps its own copy: a block's few hundred bytes beside its 2 MB of patches.
  const BinEdges edges(edges_);
  std::vector<double> part = zero();
  add_patches(part, edges, patches);
  return part;
}

void HistogramSums::combine(std::vector<double>& acc, const std::vector<double>& part) {
  for (std::size_t k = 0; k < acc.size(); ++k) acc[k] += part[k];
}

Histogram HistogramSums::histogram(const std::vector<double>& sums) const {
  Histogram histogram = empty_;
  const std::size_t count = histogram.bin_count();
  std::copy_n(sums.begin(), count, histogram.area.begin());
  histogram.below_range = sums[count];
  histogram.above_range = sums[count + 1];
  histogram.total_area = sums[count + 2];
  return histogram;
}

Histogram area_histogram(std::span<const LinearPatch> patches, ValueRange range,
                         std::uint32_t bins) {
  const HistogramSums sums(range, bins);
  return sums.histogram(ordered_reduce(
      patches.size(), kHistogramBlock, sums.zero(),
      [&](std::size_t begin, std::size_t end) {
        return sums.block(patches.subspan(begin, end - begin));
      },
      HistogramSums::combine));
}

}  // namespace ncv
