#include "statistics/error_statistics.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "sampling/lattice_triangles.hpp"
#include "statistics/area_quantiles.hpp"
#include "statistics/patch_passes.hpp"
#include "util/error.hpp"
#include "util/ordered_reduce.hpp"

namespace ncv {

namespace {

// Blocks of triangles for their counts and area sum.
constexpr std::size_t kCountBlock = std::size_t{1} << 16;

void check_distances(const SampleSet& samples, std::span<const double> d) {
  if (d.size() != samples.sample_count()) {
    throw InputError("distances",
                     fmt::format("{} values for {} samples", d.size(), samples.sample_count()));
  }
  if (d.empty()) throw InputError("distances", "there is no sample to evaluate");
  const auto bad = std::find_if(d.begin(), d.end(), [](double v) { return !std::isfinite(v); });
  if (bad != d.end()) {
    throw InputError("distances", fmt::format("sample {} has the non-finite distance {}",
                                              bad - d.begin(), *bad));
  }
}

struct TriangleCounts {
  double area = 0;
  std::uint64_t vertex_only = 0;
  std::uint64_t unsampled = 0;
};

void count_triangles(const SampleSet& samples, ErrorStatistics& stats) {
  const std::span<const double> areas = samples.triangle_areas;
  const Mesh& mesh = samples.mesh;
  const TriangleCounts counts = ordered_reduce(
      mesh.triangle_count(), kCountBlock, TriangleCounts{},
      [&](std::size_t begin, std::size_t end) {
        TriangleCounts part;
        for (std::size_t t = begin; t < end; ++t) {
          const double area = areas[t];
          part.area += area;
          if (samples.lattice_sizes[t] == 0) {
            ++part.unsampled;
          } else if (samples.lattice_sizes[t] == 2 && lattice_size(area, samples.step) < 2) {
            ++part.vertex_only;
          }
        }
        return part;
      },
      [](TriangleCounts& acc, const TriangleCounts& part) {
        acc.area += part.area;
        acc.vertex_only += part.vertex_only;
        acc.unsampled += part.unsampled;
      });
  stats.triangles = mesh.triangle_count();
  stats.workpiece_area = counts.area;
  stats.triangles_vertex_only = counts.vertex_only;
  stats.triangles_unsampled = counts.unsampled;
}

SampleExtreme extreme_at(const SampleSet& samples, std::span<const double> d, std::size_t s) {
  return {d[s], s, samples.positions[s]};
}

// Strict comparisons keep the lowest sample index among ties.
void find_extremes(const SampleSet& samples, std::span<const double> d, ErrorStatistics& stats) {
  std::size_t max = 0, min = 0;
  for (std::size_t s = 1; s < d.size(); ++s) {
    if (d[s] > d[max]) max = s;
    if (d[s] < d[min]) min = s;
  }
  stats.max = extreme_at(samples, d, max);
  stats.min = extreme_at(samples, d, min);
  stats.max_abs = std::abs(d[min]) > std::abs(d[max]) ? stats.min : stats.max;
  stats.max_abs.value = std::abs(stats.max_abs.value);
}

struct Moments {
  double area = 0;
  double sum = 0;     // integral of d
  double square = 0;  // integral of d^2
};

Moments integrate_block(std::span<const LinearPatch> patches) {
  Moments part;
  for (const LinearPatch& p : patches) {
    part.area += p.area;
    part.sum += integral(p);
    part.square += squared_integral(p);
  }
  return part;
}

void add_moments(Moments& acc, const Moments& part) {
  acc.area += part.area;
  acc.sum += part.sum;
  acc.square += part.square;
}

// The mean is docs/METHOD.md's d_mean = (1/|S1|) ∫ d dS over the lattice: divided by the whole
// workpiece area, as the paper's eq. 7, so under scheme II the skipped triangles weigh in
// with nothing (that is the paper's comparison of the schemes). RMS and spread describe
// the sampled surface. The variance integrates (d - m)^2 in a second pass rather than
// taking E[d^2] - m^2, which cancels catastrophically when the mean dwarfs the spread; that
// pass rides on the percentiles' (compute_error_statistics).
void compute_moments(const Moments& raw, ErrorStatistics& stats) {
  stats.sampled_area = raw.area;
  if (!(raw.area > 0)) return;
  stats.mean = raw.sum / (stats.workpiece_area > 0 ? stats.workpiece_area : raw.area);
  stats.rms = std::sqrt(raw.square / raw.area);
}

ToleranceAreas clip_block(std::span<const LinearPatch> patches, const Tolerance& zone) {
  ToleranceAreas part{zone};
  for (const LinearPatch& p : patches) {
    const double gouge = area_below(p, zone.lower);
    const double excess = area_above(p, zone.upper);
    part.gouge += gouge;
    part.excess += excess;
    part.within += p.area - gouge - excess;
  }
  return part;
}

void add_tolerance_areas(ToleranceAreas& acc, const ToleranceAreas& part) {
  acc.gouge += part.gouge;
  acc.excess += part.excess;
  acc.within += part.within;
}

// The first pass over the patches: the raw moments, the tolerance areas, the histogram and
// the percentiles' first step, block by block, each block's sums made while its patches are
// in cache and combined in block order per measure, so each is what its own pass gave, to
// the bit.
struct FirstPass {
  Moments raw;
  std::optional<ToleranceAreas> tolerance;
  std::vector<double> histogram;
  std::vector<double> quantiles;
};

FirstPass first_pass(const PatchSource& patches, const std::optional<Tolerance>& zone,
                     const HistogramSums& histogram, const AreaQuantiles& quantiles) {
  static_assert(kHistogramBlock == kPatchBlock);
  FirstPass zero{{}, std::nullopt, histogram.zero(), quantiles.zero()};
  if (zone) zero.tolerance = ToleranceAreas{*zone};
  return reduce_patch_blocks(
      patches, zero,
      [&](std::span<const LinearPatch> block) {
        FirstPass part{integrate_block(block), std::nullopt, histogram.block(block),
                       quantiles.block(block)};
        if (zone) part.tolerance = clip_block(block, *zone);
        return part;
      },
      [](FirstPass& acc, const FirstPass& part) {
        add_moments(acc.raw, part.raw);
        if (acc.tolerance) add_tolerance_areas(*acc.tolerance, *part.tolerance);
        HistogramSums::combine(acc.histogram, part.histogram);
        AreaQuantiles::combine(acc.quantiles, part.quantiles);
      });
}

std::vector<Percentile> compute_percentiles(const PatchSource& patches,
                                            const AreaQuantiles& quantiles,
                                            const std::vector<double>& sums,
                                            const PatchRangeVisitor& along) {
  std::vector<double> fractions;
  for (double percent : kReportedPercentiles) fractions.push_back(percent / 100);
  const std::vector<double> values = quantiles.quantiles(patches, fractions, sums, along);
  std::vector<Percentile> percentiles;
  for (std::size_t k = 0; k < values.size(); ++k) {
    percentiles.push_back({kReportedPercentiles[k], values[k]});
  }
  return percentiles;
}

}  // namespace

ErrorStatistics compute_error_statistics(const SampleSet& samples, std::span<const double> d,
                                         const std::optional<Tolerance>& tolerance,
                                         const HistogramOptions& histogram) {
  check_distances(samples, d);
  ErrorStatistics stats;
  stats.samples = d.size();
  const LatticePatches patches(samples, d);
  count_triangles(samples, stats);
  find_extremes(samples, d, stats);

  const HistogramSums histogram_sums(
      histogram.range.value_or(ValueRange{stats.min.value, stats.max.value}), histogram.bins);
  const AreaQuantiles quantiles(d);
  const FirstPass first = first_pass(patches, tolerance, histogram_sums, quantiles);
  compute_moments(first.raw, stats);
  if (tolerance) stats.tolerance = *first.tolerance;
  stats.histogram = histogram_sums.histogram(first.histogram);
  const Moments& raw = first.raw;
  const double sampled_mean = raw.area > 0 ? raw.sum / raw.area : 0.0;
  OrderedPatchSum deviation(
      [sampled_mean](const LinearPatch& p) { return squared_integral(p, sampled_mean); });
  stats.percentiles =
      compute_percentiles(patches, quantiles, first.quantiles,
                          [&](std::span<const LinearPatch> range) { deviation.add(range); });
  if (raw.area > 0) stats.std_dev = std::sqrt(deviation.sum() / raw.area);
  return stats;
}

}  // namespace ncv
