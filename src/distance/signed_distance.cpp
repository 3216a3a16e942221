#include "distance/signed_distance.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <thread>

#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "distance/side_rule.hpp"
#include "search/closest_point_search.hpp"
#include "search/group_search.hpp"
#include "search/query_order.hpp"
#include "search/sample_searcher.hpp"
#include "util/error.hpp"

namespace ncv {
namespace {

void check_normals(std::span<const Vec3> points, std::span<const Vec3> sample_normals,
                   SignMethod method) {
  if (method == SignMethod::paper && sample_normals.size() != points.size()) {
    throw UsageError(
        fmt::format("the paper's sign rule needs one sample normal per point ({} "
                    "normals for {} points)",
                    sample_normals.size(), points.size()));
  }
}

bool usable(const Vec3& p) {
  return is_finite(p) && max_abs(p) <= kMaxCoordinate;
}

static_assert(kDistanceBlockSize <= kMostOrderedPoints);

// Everything one thread needs: its searcher (which owns the per-triangle stamps), its share
// of the counters, and a block's points in the order searched and their hits (made once: a
// hit's default values written for every block were a tenth of the uncut slot's step).
struct Worker {
  std::optional<GroupSearcher> groups;
  std::optional<SampleSearcher> single;
  SearchCounters counters;
  std::array<std::uint16_t, kDistanceBlockSize> order;
  std::array<Vec3, kDistanceBlockSize> local;
  std::array<Vec3, kDistanceBlockSize> queries;
  std::array<ClosestHit, kDistanceBlockSize> hits;
};

class SignedDistanceJob {
 public:
  SignedDistanceJob(const ReferenceSurface& nominal, const SearchIndex* grid,
                    std::span<const Vec3> points, std::span<const Vec3> normals,
                    const SideRule& side, std::span<const std::uint32_t> order)
      : nominal_(nominal),
        grid_(grid),
        points_(points),
        normals_(normals),
        side_(side),
        order_(order),
        head_(points.size() - order.size()) {}

  // The points at places begin..end of the measuring order, begin at a block's start; every
  // block starts its search afresh. A block holding an unusable point is not measured
  // (first_unusable() names the lowest).
  void run(DistanceField& field, std::size_t begin, std::size_t end) {
    Worker& worker = workers_.local();
    for (std::size_t block = begin; block < end; block += kDistanceBlockSize) {
      const std::size_t count = std::min(kDistanceBlockSize, end - block);
      if (!to_local(block, count, worker)) continue;
      if (grid_ && grid_->groups_pay()) {
        if (!worker.groups) worker.groups.emplace(*grid_);
        measure_in_groups(field, block, count, worker);
      } else {
        if (grid_ && !worker.single) worker.single.emplace(*grid_);
        measure_one_by_one(field, block, count, worker);
      }
    }
  }

  // The lowest index of a point that is not finite or lies beyond kMaxCoordinate, or none.
  std::optional<std::size_t> first_unusable() const {
    const std::size_t first = first_unusable_.load();
    return first < points_.size() ? std::optional<std::size_t>(first) : std::nullopt;
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
  // The number of the point at place k of the measuring order.
  std::size_t point_at(std::size_t k) const { return k < head_ ? k : order_[k - head_]; }

  // The block's points in the surface's frame, into worker.local; false (and its unusable
  // points noted) when one is unusable, checked in the same pass as the points are read (a
  // pass of its own read the 30 MB of a paper-scale job's points again).
  bool to_local(std::size_t block, std::size_t count, Worker& worker) {
    bool all = true;
    for (std::size_t k = 0; k < count; ++k) {
      const Vec3 p = points_[point_at(block + k)];
      all &= usable(p);
      worker.local[k] = nominal_.to_local(p);
    }
    if (all) return true;
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = point_at(block + k);
      if (usable(points_[i])) continue;
      std::size_t first = first_unusable_.load();
      while (i < first && !first_unusable_.compare_exchange_weak(first, i)) {
      }
    }
    return false;
  }

  // A block of points in its spatial order (query_order.hpp), in groups of consecutive ones
  // (group_search.hpp).
  void measure_in_groups(DistanceField& field, std::size_t block, std::size_t count,
                         Worker& worker) {
    auto& order = worker.order;
    auto& local = worker.local;
    auto& queries = worker.queries;
    auto& hits = worker.hits;
    if (runs_lie_apart({local.data(), count}, kGroupSize, 0.5 * worker.groups->reach())) {
      spatial_order({local.data(), count}, {order.data(), count});
      for (std::size_t k = 0; k < count; ++k) queries[k] = local[order[k]];
    } else {
      for (std::size_t k = 0; k < count; ++k) {
        order[k] = static_cast<std::uint16_t>(k);
        queries[k] = local[k];
      }
    }
    worker.groups->forget();
    for (std::size_t k = 0; k < count;) {
      k += worker.groups->closest({queries.data() + k, count - k}, {hits.data() + k, count - k},
                                  worker.counters);
    }
    for (std::size_t k = 0; k < count; ++k) {
      store(field, point_at(block + order[k]), queries[k], hits[k]);
    }
  }

  // A block of points in their order, each from its predecessor's closest triangle (over the
  // grid), or by brute force.
  void measure_one_by_one(DistanceField& field, std::size_t block, std::size_t count,
                          Worker& worker) {
    if (worker.single) worker.single->forget();
    for (std::size_t k = 0; k < count; ++k) {
      const Vec3 p = worker.local[k];
      store(field, point_at(block + k), p,
            worker.single ? worker.single->closest(p, worker.counters)
                          : brute_force_closest(nominal_.corners(), p, worker.counters));
    }
  }

  void store(DistanceField& field, std::size_t i, Vec3 local, const ClosestHit& hit) const {
    const Vec3 normal = side_.method() == SignMethod::paper ? normals_[i] : Vec3(0, 0, 0);
    field.distance[i] = side_.signed_value(local, hit, normal);
    field.closest_face[i] = hit.triangle;
  }

  const ReferenceSurface& nominal_;
  const SearchIndex* grid_;
  std::span<const Vec3> points_;
  std::span<const Vec3> normals_;
  const SideRule& side_;
  std::span<const std::uint32_t> order_;  // the points after the first head_, in their order
  std::size_t head_;                      // points measured in their own order first
  tbb::enumerable_thread_specific<Worker> workers_;
  std::atomic<std::size_t> first_unusable_{std::numeric_limits<std::size_t>::max()};
};

}  // namespace

SignMethod resolve_sign_method(const ReferenceSurface& nominal, SignMethod requested) {
  return requested == SignMethod::automatic ? nominal.automatic_sign_method() : requested;
}

namespace {

DistanceField measure(const ReferenceSurface& nominal, const SearchIndex* grid,
                      std::span<const Vec3> points, std::span<const Vec3> sample_normals,
                      const SideRule& side, SearchStatistics* statistics,
                      const DistanceProgress& progress, std::span<const std::uint32_t> order) {
  check_normals(points, sample_normals, side.method());
  if (order.size() > points.size()) {
    throw UsageError(
        fmt::format("a measuring order of {} places for {} points", order.size(), points.size()));
  }
  const std::size_t n = points.size();
  DistanceField field;
  field.distance.resize(n);
  field.closest_face.resize(n);

  SignedDistanceJob job(nominal, grid, points, sample_normals, side, order);
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
  if (const std::optional<std::size_t> bad = job.first_unusable()) {
    throw InputError("query points",
                     fmt::format("point {} is not finite or beyond {}", *bad, kMaxCoordinate));
  }
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
  return measure(index.surface(), &index, points, sample_normals, side, statistics, progress, {});
}

DistanceField compute_signed_distances(const SearchIndex& index, std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, const SideRule& side,
                                       SearchStatistics* statistics,
                                       const DistanceProgress& progress,
                                       std::span<const std::uint32_t> order) {
  return measure(index.surface(), &index, points, sample_normals, side, statistics, progress,
                 order);
}

DistanceField compute_signed_distances(const ReferenceSurface& surface,
                                       std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, SignMethod method,
                                       SearchStatistics* statistics,
                                       const DistanceProgress& progress) {
  const SideRule side(surface, resolve_sign_method(surface, method));
  return measure(surface, nullptr, points, sample_normals, side, statistics, progress, {});
}

DistanceField compute_signed_distances(const ReferenceSurface& surface,
                                       std::span<const Vec3> points,
                                       std::span<const Vec3> sample_normals, const SideRule& side,
                                       SearchStatistics* statistics,
                                       const DistanceProgress& progress) {
  return measure(surface, nullptr, points, sample_normals, side, statistics, progress, {});
}

}  // namespace ncv
