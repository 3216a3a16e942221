#include "distance_step.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "progress.hpp"
#include "sample_normals.hpp"
#include "stopwatch.hpp"

namespace ncv {
namespace {

// Share of the smaller box's volume inside the other, with boxes grown by 1 % of the
// larger diagonal so flat parts still have a volume.
double overlap_share(const BoundingBox& a, const BoundingBox& b) {
  const double pad = 0.01 * std::max(a.diagonal(), b.diagonal());
  double inter = 1, va = 1, vb = 1;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = std::max(a.min[axis], b.min[axis]) - pad;
    const double hi = std::min(a.max[axis], b.max[axis]) + pad;
    inter *= std::max(0.0, hi - lo);
    va *= a.max[axis] - a.min[axis] + 2 * pad;
    vb *= b.max[axis] - b.min[axis] + 2 * pad;
  }
  return inter / std::min(va, vb);
}

void warn_if_apart(const SampleSet& samples, const NominalGrid& grid) {
  const BoundingBox workpiece = bounding_box(samples.workpiece);
  const BoundingBox nominal = bounding_box(grid.mesh);
  const double share = overlap_share(workpiece, nominal);
  if (share < 0.5) {
    spdlog::warn(
        "the workpiece ({}) and the nominal ({}) barely overlap ({:.0f} % of the "
        "smaller bounding box): a wrong file, unit or coordinate frame?",
        samples.workpiece_source, grid.nominal_source, 100 * share);
  }
  const double ratio = workpiece.diagonal() / std::max(nominal.diagonal(), 1e-300);
  if (ratio > 5 || ratio < 0.2) {
    spdlog::warn("the workpiece is {:.3g} times the size of the nominal: a unit mismatch?", ratio);
  }
}

}  // namespace

DistanceSet measure_distances(SampleSet samples, const NominalGrid& grid,
                              const DistanceStepOptions& options, double* seconds) {
  warn_if_apart(samples, grid);
  const SignMethod method = resolve_sign_method(*grid.nominal, options.sign);
  const std::vector<Vec3> normals =
      method == SignMethod::paper ? sample_normals(samples) : std::vector<Vec3>{};

  Stopwatch clock;
  SearchStatistics statistics;
  Progress progress("distance", samples.sample_count());
  DistanceSet result;
  result.field = compute_signed_distances(
      *grid.nominal, options.brute_force ? nullptr : &grid.grid, samples.positions, normals, method,
      &statistics, [&](std::size_t done, std::size_t) { progress.update(done); });
  progress.finish();
  if (seconds) *seconds = clock.seconds();

  result.samples = std::move(samples);
  result.nominal = {grid.nominal_source, grid.nominal_hash, grid.mesh.triangle_count(),
                    bounding_box(grid.mesh)};
  result.sign_method = std::string(sign_method_name(method));
  result.search = options.brute_force ? "brute-force" : "grid";
  result.triangles_tested_per_sample = statistics.triangles_per_query();
  return result;
}

void log_distance_report(const DistanceSet& d, double seconds) {
  const auto samples = static_cast<double>(d.samples.sample_count());
  spdlog::info(
      "{} samples against {} nominal triangles in {:.3f} s ({:.3g} samples/s); {} "
      "search, {:.1f} triangles tested per sample; sign by {}",
      d.samples.sample_count(), d.nominal.triangles, seconds, samples / std::max(seconds, 1e-9),
      d.search, d.triangles_tested_per_sample, d.sign_method);
}

}  // namespace ncv
