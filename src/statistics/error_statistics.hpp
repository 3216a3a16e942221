// The error measures of docs/METHOD.md "Error measures" (paper eqs. 5-8), from the signed
// distance of every sample.
//
// Every area-weighted measure treats the error as the piecewise-linear interpolant of the
// sample errors over the lattice sub-triangles (lattice_triangles.hpp), and evaluates it
// exactly for that interpolant: the mean is paper eq. 8 summed, RMS and standard deviation
// integrate its square in closed form, and the percentiles, histogram and tolerance areas
// all come from the exact distribution of its values over the surface. The mean divides by
// the whole workpiece area |S1| (paper eq. 7); the other measures describe the
// sampled surface, which is the whole of it under scheme I.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "sampling/sampling.hpp"
#include "statistics/area_histogram.hpp"
#include "statistics/sample_extreme.hpp"
#include "statistics/tolerance.hpp"

namespace ncv {

// Area-weighted percentiles reported, in percent.
inline constexpr double kReportedPercentiles[] = {1, 5, 50, 95, 99};

struct Percentile {
  double percent = 0;
  double value = 0;
};

struct ToleranceAreas {
  Tolerance tolerance;
  double within = 0;  // area where lower <= d <= upper
  double excess = 0;  // area where d > upper
  double gouge = 0;   // area where d < lower
};

struct ErrorStatistics {
  std::uint64_t samples = 0;
  std::uint64_t triangles = 0;
  std::uint64_t triangles_vertex_only = 0;  // n' rounded below 2, sampled at the corners
  std::uint64_t triangles_unsampled = 0;    // skipped by scheme II
  double workpiece_area = 0;
  double sampled_area = 0;  // total area of the lattice sub-triangles

  SampleExtreme max;      // d_max, eq. 5
  SampleExtreme min;      // d_min, eq. 6
  SampleExtreme max_abs;  // |d| max, the one-sided Hausdorff distance (value is >= 0)
  double mean = 0;        // eq. 7 by eq. 8, over |S1|
  double rms = 0;
  double std_dev = 0;
  std::vector<Percentile> percentiles;  // kReportedPercentiles; NaN when sampled_area is 0
  Histogram histogram;
  std::optional<ToleranceAreas> tolerance;

  double share(double area) const { return sampled_area > 0 ? area / sampled_area : 0; }
};

// d holds one signed distance per sample. Throws InputError when d does not match the
// samples, holds a non-finite value, or there is no sample at all; UsageError for bad
// histogram options. The result does not depend on the number of threads.
ErrorStatistics compute_error_statistics(const SampleSet& samples, std::span<const double> d,
                                         const std::optional<Tolerance>& tolerance,
                                         const HistogramOptions& histogram = {});

}  // namespace ncv
