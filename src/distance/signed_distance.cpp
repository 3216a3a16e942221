#include "distance/signed_distance.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <optional>
#include <thread>

#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "distance/side_rule.hpp"
#include "search/closest_point_search.hpp"
#include "search/sample_searcher.hpp"
#include "util/error.hpp"

namespace ncv {
namespace {

void check_inputs(std::span<const Vec3> points, std::span<const Vec3> sample_normals,
                  SignMethod method) {
  // The first bad point, found in parallel (the lowest index, whatever the thread count).
  const std::size_t bad = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, points.size(), 1 << 14), points.size(),
      [&](const tbb::blocked_range<std::size_t>& range, std::size_t first) {
        for (std::size_t i = range.begin(); i < range.end() && i < first; ++i) {
          const Vec3 p = points[i];
          if (!is_finite(p) || max_abs(p) > kMaxCoordinate) {
            return i;
          }
        }
        return first;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (bad < points.size()) {
    throw InputError("query points",
                     fmt::format("point {} is not finite or beyond {}", bad, kMaxCoordinate));
  }
  if (method == SignMethod::paper && sample_normals.size() != points.size()) {
    throw UsageError(
        fmt::format("the paper's sign rule needs one sample normal per point ({} "
                    "normals for {} points)",
                    sample_normals.size(), points.size()));
  }
}

// Everything one thread needs: a sample searcher (its grid searchers own the per-triangle
// stamps) and its share of the counters.
struct Worker {
  std::optional<SampleSearcher> search;
  SearchCounters counters;
};

class SignedDistanceJob {
 public:
  SignedDistanceJob(const ReferenceSurface& nominal, const SearchIndex* grid,
                    std::span<const Vec3> points, std::span<const Vec3> normals,
                    const SideRule& side)
      : nominal_(nominal), grid_(grid), points_(points), normals_(normals), side_(side) {}

  void run(DistanceField& field, std::size_t begin, std::size_t end) {
    Worker& worker = workers_.local();
    if (grid_ && !worker.search) worker.search.emplace(*grid_);
    const bool paper = side_.method() == SignMethod::paper;
    for (std::size_t i = begin; i < end; ++i) {
      if (worker.search && i % kDistanceBlockSize == 0) worker.search->forget();
      const Vec3 p = nominal_.to_local(points_[i]);
      const ClosestHit hit = worker.search
                                 ? worker.search->closest(p, worker.counters)
                                 : brute_force_closest(nominal_.corners(), p, worker.counters);
      field.distance[i] = side_.signed_value(p, hit, paper ? normals_[i] : Vec3(0, 0, 0));
      field.closest_face[i] = hit.triangle;
    }
  }

  SearchCounters counters() {
    SearchCounters total;
    for (const Worker& worker : workers_) {
      total.triangles_tested += worker.counters.triangles_tested;
      total.triangles_considered += worker.counters.triangles_considered;
      total.cells_visited += worker.counters.cells_visited;
    }
    return total;
  }

 private:
  const ReferenceSurface& nominal_;
  const SearchIndex* grid_;
  std::span<const Vec3> points_;
  std::span<const Vec3> normals_;
  const SideRule& side_;
  tbb::enumerable_thread_specific<Worker> workers_;
};

}  // namespace

SignMethod resolve_sign_method(const ReferenceSurface& nominal, SignMethod requested) {
  return requested == SignMethod::automatic ? nominal.automatic_sign_method() : requested;
}

namespace {

DistanceField measure(const ReferenceSurface& nominal, const SearchIndex* grid,
                      std::span<const Vec3> points, std::span<const Vec3> sample_normals,
                      const SideRule& side, SearchStatistics* statistics,
                      const DistanceProgress& progress) {
  check_inputs(points, sample_normals, side.method());
  const std::size_t n = points.size();
  DistanceField field;
  field.distance.resize(n);
  field.closest_face.resize(n);

  SignedDistanceJob job(nominal, grid, points, sample_normals, side);
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<std::size_t> done{0};
  const std::size_t blocks = (n + kDistanceBlockSize - 1) / kDistanceBlockSize;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      const std::size_t begin = range.begin() * kDistanceBlockSize;
                      const std::size_t end = std::min(n, range.end() * kDistanceBlockSize);
                      job.run(field, begin, end);
                      const std::size_t finished = done += end - begin;
                      if (progress && std::this_thread::get_id() == caller) progress(finished, n);
                    });
  if (progress) progress(n, n);

  if (statistics) {
    const SearchCounters counters = job.counters();
    statistics->queries = n;
    statistics->triangles_tested = counters.triangles_tested;
    statistics->triangles_considered = counters.triangles_considered;
    statistics->cells_visited = counters.cells_visited;
  }
  return field;
}

}  // namespace

DistanceField compute_signed_distances(const SearchIndex& index, std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, SignMethod method,
                                       SearchStatistics* statistics,
                                       const DistanceProgress& progress) {
  const SideRule side(index.surface(), resolve_sign_method(index.surface(), method));
  return measure(index.surface(), &index, points, sample_normals, side, statistics, progress);
}

DistanceField compute_signed_distances(const SearchIndex& index, std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, const SideRule& side,
                                       SearchStatistics* statistics,
                                       const DistanceProgress& progress) {
  return measure(index.surface(), &index, points, sample_normals, side, statistics, progress);
}

DistanceField compute_signed_distances(const ReferenceSurface& surface,
                                       std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, SignMethod method,
                                       SearchStatistics* statistics,
                                       const DistanceProgress& progress) {
  const SideRule side(surface, resolve_sign_method(surface, method));
  return measure(surface, nullptr, points, sample_normals, side, statistics, progress);
}

DistanceField compute_signed_distances(const ReferenceSurface& surface,
                                       std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, const SideRule& side,
                                       SearchStatistics* statistics,
                                       const DistanceProgress& progress) {
  return measure(surface, nullptr, points, sample_normals, side, statistics, progress);
}

}  // namespace ncv
