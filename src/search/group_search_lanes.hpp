// The group search's work (group_search.hpp) for kLanes points a vector: included by one
// translation unit per instruction set after its `#pragma GCC target`, so that everything
// here is compiled for that target (closest_point_lanes.hpp says why). Internal linkage only,
// so the copies of the three units never stand in for each other. The including unit
// includes search/group_search_state.hpp and the standard headers first: only this file's
// definitions and the kernel's take the target.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "geometry/closest_point_lanes.hpp"
#include "search/box_lanes.hpp"
#include "search/group_search_state.hpp"

namespace ncv {
namespace {

double interval_gap(double lo, double hi, double a, double b) {
  return std::max(std::max(a - hi, lo - b), 0.0);
}

// The group's points and its lanes' bests as plain arrays, kLanes to a vector.
template <int kLanes>
struct Group {
  using Real = typename LaneTypes<kLanes>::Real;
  using Mask = typename LaneTypes<kLanes>::Mask;

  int queries = 0;  // lanes holding a query
  int vectors = 0;  // vectors holding one
  alignas(64) double x[kGroupSize], y[kGroupSize], z[kGroupSize];
  // Per lane: the best so far (squared distance, point, triangle as a double, feature) and
  // its bound (best + margin)^2.
  alignas(64) double best_sq[kGroupSize], best_x[kGroupSize], best_y[kGroupSize],
      best_z[kGroupSize], best_t[kGroupSize], bound_sq[kGroupSize];
  alignas(64) std::int64_t best_f[kGroupSize];
  double lo[3], hi[3];  // the group's box
  float float_lo[3], float_hi[3];
  double scale = 0, margin = 0;
  double group_bound_sq = 0;                         // the largest lane bound
  float limit = 0;                                   // its root as the float box filter's limit
  std::array<std::int64_t, 3> first{}, last{};       // the cells of shell 0
  std::array<std::int64_t, 3> seen_lo{}, seen_hi{};  // the visited box

  static Real real(const double* lanes, int v) {
    Real r;
    std::memcpy(&r, lanes + v * kLanes, sizeof r);
    return r;
  }
  static Mask mask(const std::int64_t* lanes, int v) {
    Mask r;
    std::memcpy(&r, lanes + v * kLanes, sizeof r);
    return r;
  }
  template <typename V, typename T>
  static void store(T* lanes, int v, V r) {
    std::memcpy(lanes + v * kLanes, &r, sizeof r);
  }
};

// As many of the first queries as lie within `reach` across (at most kGroupSize) into the
// lanes; lanes past the last query repeat it (they change no box and are not read). Returns
// how many.
template <int kLanes>
std::size_t load_group(Group<kLanes>& g, std::span<const Vec3> queries, double reach_sq) {
  const std::size_t most = std::min(queries.size(), kGroupSize);
  double lo[3], hi[3];
  for (int axis = 0; axis < 3; ++axis) lo[axis] = hi[axis] = queries[0][axis];
  std::size_t n = 1;
  for (; n < most; ++n) {
    double across_sq = 0;
    double grown_lo[3], grown_hi[3];
    for (int axis = 0; axis < 3; ++axis) {
      grown_lo[axis] = std::min(lo[axis], queries[n][axis]);
      grown_hi[axis] = std::max(hi[axis], queries[n][axis]);
      across_sq += (grown_hi[axis] - grown_lo[axis]) * (grown_hi[axis] - grown_lo[axis]);
    }
    if (across_sq > reach_sq) break;
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = grown_lo[axis];
      hi[axis] = grown_hi[axis];
    }
  }
  g.queries = static_cast<int>(n);
  g.vectors = (g.queries + kLanes - 1) / kLanes;
  double scale = 0;
  for (int axis = 0; axis < 3; ++axis) {
    g.lo[axis] = lo[axis];
    g.hi[axis] = hi[axis];
  }
  for (int k = 0; k < g.vectors * kLanes; ++k) {
    const Vec3 q = queries[std::min(static_cast<std::size_t>(k), n - 1)];
    g.x[k] = q[0];
    g.y[k] = q[1];
    g.z[k] = q[2];
    g.best_sq[k] = std::numeric_limits<double>::infinity();
    g.best_t[k] = std::numeric_limits<double>::infinity();
    g.bound_sq[k] = std::numeric_limits<double>::infinity();
  }
  for (int axis = 0; axis < 3; ++axis) {
    scale = std::max({scale, std::fabs(g.lo[axis]), std::fabs(g.hi[axis])});
    g.float_lo[axis] = float_at_or_below(g.lo[axis]);
    g.float_hi[axis] = float_at_or_above(g.hi[axis]);
  }
  g.scale = scale;
  g.group_bound_sq = std::numeric_limits<double>::infinity();
  g.limit = std::numeric_limits<float>::infinity();
  return n;
}

// The group's bound from its lanes'.
template <int kLanes>
void update_group_bound(Group<kLanes>& g) {
  using G = Group<kLanes>;
  typename G::Real largest = G::real(g.bound_sq, 0);
  for (int v = 1; v < g.vectors; ++v) {
    const typename G::Real b = G::real(g.bound_sq, v);
    largest = largest > b ? largest : b;
  }
  double most = largest[0];
  for (int k = 1; k < kLanes; ++k) most = std::max(most, largest[k]);
  g.group_bound_sq = most;
  g.limit = box_filter_limit(std::sqrt(most), g.scale);
}

// Whether any lane of vector v has its bound reaching the box [lo, hi] (each lane's squared
// gap to it in doubles: a few ulps of the coordinate scale, far inside the bounds' margin).
template <int kLanes>
[[gnu::always_inline]] inline bool reaches(const Group<kLanes>& g, const PointLanes<kLanes>& p,
                                           int v, const double* lo, const double* hi) {
  using G = Group<kLanes>;
  using Real = typename G::Real;
  const Real zero = Real{};
  const Real* axes[3] = {&p.x, &p.y, &p.z};
  Real gap_sq = zero;
  for (int axis = 0; axis < 3; ++axis) {
    const Real below = lo[axis] - *axes[axis];
    const Real above = *axes[axis] - hi[axis];
    Real gap = below > above ? below : above;
    gap = gap > zero ? gap : zero;
    gap_sq += gap * gap;
  }
  return any_lane<kLanes>(gap_sq <= G::real(g.bound_sq, v));
}

// Vector v's lanes take the kernel's result r for triangle `index` where it is better (the
// lesser squared distance, the lower index among ties); true when a lane did.
template <int kLanes>
[[gnu::always_inline]] inline bool take(Group<kLanes>& g, int v,
                                        const TrianglePointLanes<kLanes>& r,
                                        typename Group<kLanes>::Real index) {
  using G = Group<kLanes>;
  using Real = typename G::Real;
  using Mask = typename G::Mask;
  const Real best_sq = G::real(g.best_sq, v);
  const Real best_t = G::real(g.best_t, v);
  const Mask better = (r.squared < best_sq) | ((r.squared == best_sq) & (index < best_t));
  if (!any_lane<kLanes>(better)) return false;
  const Real new_sq = better ? r.squared : best_sq;
  G::store(g.best_sq, v, new_sq);
  G::store(g.best_t, v, better ? index : best_t);
  G::store(g.best_x, v, better ? r.x : G::real(g.best_x, v));
  G::store(g.best_y, v, better ? r.y : G::real(g.best_y, v));
  G::store(g.best_z, v, better ? r.z : G::real(g.best_z, v));
  G::store(g.best_f, v, better ? r.feature : G::mask(g.best_f, v));
  const Real bound = lane_sqrt<kLanes>(new_sq) + g.margin;
  G::store(g.bound_sq, v, bound * bound);
  return true;
}

struct MeasuredTriangle {
  LaneTriangle corners;
  double lo[3], hi[3];  // its box
};

[[gnu::always_inline]] inline MeasuredTriangle measured_triangle(const TriangleCorners& corners) {
  MeasuredTriangle m{lane_triangle(corners), {}, {}};
  for (int axis = 0; axis < 3; ++axis) {
    m.lo[axis] = std::min(std::min(m.corners.a[axis], m.corners.b[axis]), m.corners.c[axis]);
    m.hi[axis] = std::max(std::max(m.corners.a[axis], m.corners.b[axis]), m.corners.c[axis]);
  }
  return m;
}

template <int kLanes>
[[gnu::always_inline]] inline void count_tests(const Group<kLanes>& g, int v,
                                               SearchCounters& counters) {
  counters.triangles_tested += static_cast<std::uint64_t>(std::min(kLanes, g.queries - v * kLanes));
}

// Measures triangle t against every vector of the group with a lane whose bound reaches the
// triangle's box (every vector when `all`); true when a lane improved.
template <int kLanes>
bool measure(Group<kLanes>& g, const TriangleCorners& corners, std::uint32_t t, bool all,
             SearchCounters& counters) {
  using G = Group<kLanes>;
  using Real = typename G::Real;
  const MeasuredTriangle m = measured_triangle(corners);
  const Real index = Real{} + static_cast<double>(t);
  bool improved = false;
  for (int v = 0; v < g.vectors; ++v) {
    const PointLanes<kLanes> p{G::real(g.x, v), G::real(g.y, v), G::real(g.z, v)};
    if (!all && !reaches(g, p, v, m.lo, m.hi)) continue;
    count_tests(g, v, counters);
    improved |= take(g, v, closest_point_on_triangle_lanes<kLanes>(p, m.corners), index);
  }
  return improved;
}

// Two triangles measured as measure() measures each, both kernels of a vector computed
// before either result is taken: two independent chains of work the core overlaps. The
// bests are the least (squared distance, index) pairs in any order; the second triangle's
// boxes are checked against the bounds before the first's results, which only tests more.
template <int kLanes>
bool measure_pair(Group<kLanes>& g, const TriangleCorners& c0, std::uint32_t t0,
                  const TriangleCorners& c1, std::uint32_t t1, SearchCounters& counters) {
  using G = Group<kLanes>;
  using Real = typename G::Real;
  const MeasuredTriangle m0 = measured_triangle(c0), m1 = measured_triangle(c1);
  const Real index0 = Real{} + static_cast<double>(t0);
  const Real index1 = Real{} + static_cast<double>(t1);
  bool improved = false;
  for (int v = 0; v < g.vectors; ++v) {
    const PointLanes<kLanes> p{G::real(g.x, v), G::real(g.y, v), G::real(g.z, v)};
    const bool first = reaches(g, p, v, m0.lo, m0.hi);
    const bool second = reaches(g, p, v, m1.lo, m1.hi);
    if (first && second) {
      count_tests(g, v, counters);
      count_tests(g, v, counters);
      const TrianglePointLanes<kLanes> r0 = closest_point_on_triangle_lanes<kLanes>(p, m0.corners);
      const TrianglePointLanes<kLanes> r1 = closest_point_on_triangle_lanes<kLanes>(p, m1.corners);
      improved |= take(g, v, r0, index0);
      improved |= take(g, v, r1, index1);
    } else if (first || second) {
      const MeasuredTriangle& m = first ? m0 : m1;
      count_tests(g, v, counters);
      improved |= take(g, v, closest_point_on_triangle_lanes<kLanes>(p, m.corners),
                       first ? index0 : index1);
    }
  }
  return improved;
}

// Gathers the triangles of cell `cell` whose boxes may be within the group's bound of its box
// and that this group has not met yet.
void gather_cell(GroupSearcher::State& s, const GroupLevel& level, const LaneBox& near,
                 std::uint64_t cell, SearchCounters& counters) {
  ++counters.cells_visited;
  const std::uint64_t begin = level.grid->cell_offsets[cell];
  const std::uint64_t end = level.grid->cell_offsets[cell + 1];
  counters.triangles_considered += end - begin;
  for (std::uint64_t first = begin - begin % kBoxLanes; first < end; first += kBoxLanes) {
    const BoxBlock& block = level.boxes[first / kBoxLanes];
    float squared[kBoxLanes];
    unsigned lanes = near_lanes(block, near, squared);
    if (first < begin) lanes &= ~0u << (begin - first);
    if (end - first < kBoxLanes) lanes &= (1u << (end - first)) - 1;
    while (lanes != 0) {
      const int lane = __builtin_ctz(lanes);
      lanes &= lanes - 1;
      const std::uint32_t t = block.triangle[lane];
      if (s.stamps[t] == s.epoch) continue;
      s.stamps[t] = s.epoch;
      s.candidates.push_back({squared[lane], t});
    }
  }
}

template <int kLanes>
double cell_gap(const GroupLevel& level, const Group<kLanes>& g, int axis, std::int64_t i) {
  return interval_gap(g.lo[axis], g.hi[axis],
                      ncv::cell_bound(level.origin[axis], level.grid->cell_size, i),
                      ncv::cell_bound(level.origin[axis], level.grid->cell_size, i + 1));
}

// The cells of the box seen_lo..seen_hi outside the box first - m + 1 .. last + m - 1 (every
// cell of it when m == 0), skipping slabs, rows and cells farther from the group's box than
// its bound.
template <int kLanes>
void gather_shell(GroupSearcher::State& s, const GroupLevel& level, const Group<kLanes>& g,
                  std::int64_t m, SearchCounters& counters) {
  const LaneBox near = lane_box(g.float_lo, g.float_hi, g.limit);
  for (std::int64_t z = g.seen_lo[2]; z <= g.seen_hi[2]; ++z) {
    const double gz = cell_gap(level, g, 2, z);
    const double gz_sq = gz * gz;
    if (gz_sq > g.group_bound_sq) continue;
    const bool z_face = m == 0 || z == g.first[2] - m || z == g.last[2] + m;
    for (std::int64_t y = g.seen_lo[1]; y <= g.seen_hi[1]; ++y) {
      const double gy = cell_gap(level, g, 1, y);
      const double gyz_sq = gz_sq + gy * gy;
      if (gyz_sq > g.group_bound_sq) continue;
      const bool whole_row = z_face || y == g.first[1] - m || y == g.last[1] + m;
      const std::int64_t low_x = g.first[0] - m, high_x = g.last[0] + m;
      // A whole row, or its two cells on the shell.
      for (std::int64_t x = whole_row ? g.seen_lo[0] : low_x; x <= g.seen_hi[0];
           x = whole_row || x != low_x ? x + 1 : high_x) {
        if (x < 0) continue;
        const double gx = cell_gap(level, g, 0, x);
        if (gyz_sq + gx * gx > g.group_bound_sq) continue;
        gather_cell(
            s, level, near,
            level.grid->cell_index(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                                   static_cast<std::uint32_t>(z)),
            counters);
      }
    }
  }
}

// dist^2(group box, closure(G \ V)), V the visited box: the single query's stopping rule
// (closest_point_search.cpp) with the group's box for the point.
template <int kLanes>
double unvisited_squared_distance(const GroupLevel& level, const Group<kLanes>& g) {
  std::array<double, 3> outside;
  for (int axis = 0; axis < 3; ++axis) {
    const double gap =
        interval_gap(g.lo[axis], g.hi[axis], level.box_min[axis], level.box_max[axis]);
    outside[axis] = gap * gap;
  }
  const std::array<double, 3> others{outside[1] + outside[2], outside[2] + outside[0],
                                     outside[0] + outside[1]};
  const double h = level.grid->cell_size;
  double nearest = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    if (g.seen_lo[axis] > 0) {
      const double gap = interval_gap(g.lo[axis], g.hi[axis], level.box_min[axis],
                                      ncv::cell_bound(level.origin[axis], h, g.seen_lo[axis]));
      nearest = std::min(nearest, others[axis] + gap * gap);
    }
    if (g.seen_hi[axis] < level.last_cell[axis]) {
      const double gap = interval_gap(g.lo[axis], g.hi[axis],
                                      ncv::cell_bound(level.origin[axis], h, g.seen_hi[axis] + 1),
                                      level.box_max[axis]);
      nearest = std::min(nearest, others[axis] + gap * gap);
    }
  }
  return nearest;
}

template <int kLanes>
bool covers_grid(const GroupLevel& level, const Group<kLanes>& g) {
  for (int axis = 0; axis < 3; ++axis) {
    if (g.seen_lo[axis] > 0 || g.seen_hi[axis] < level.last_cell[axis]) return false;
  }
  return true;
}

// Measures the candidates gathered since `from`: the one with the nearest box first, alone
// (its triangle is the likeliest to lower the bounds the others are checked against), then
// the others two at a time (measure_pair), each checked against the group's limit first.
template <int kLanes>
void measure_candidates(GroupSearcher::State& s, Group<kLanes>& g, std::size_t from,
                        SearchCounters& counters) {
  GroupCandidate* found = s.candidates.data() + from;
  const std::size_t count = s.candidates.size() - from;
  if (count == 0) return;
  std::size_t nearest = 0;
  for (std::size_t k = 0; k < count; ++k) {
    if (found[k].squared < found[nearest].squared) nearest = k;
  }
  if (nearest != 0) std::swap(found[0], found[nearest]);
  const auto alone = [&](const GroupCandidate& c) {
    if (measure(g, s.triangles[c.triangle], c.triangle, false, counters)) update_group_bound(g);
  };
  if (found[0].squared <= g.limit) alone(found[0]);
  const GroupCandidate* waiting = nullptr;  // a candidate in, without its partner yet
  for (std::size_t k = 1; k < count; ++k) {
    if (found[k].squared > g.limit) continue;
    if (!waiting) {
      waiting = &found[k];
      continue;
    }
    if (measure_pair(g, s.triangles[waiting->triangle], waiting->triangle,
                     s.triangles[found[k].triangle], found[k].triangle, counters)) {
      update_group_bound(g);
    }
    waiting = nullptr;
  }
  if (waiting && waiting->squared <= g.limit) alone(*waiting);
}

template <int kLanes>
std::size_t search_group(GroupSearcher::State& s, std::span<const Vec3> queries,
                         std::span<ClosestHit> hits, SearchCounters& counters) {
  Group<kLanes> g;
  const std::size_t n = load_group(g, queries, s.reach_sq);
  if (n == 1) {
    // A point apart from the next: searched on its own, from its predecessor's triangle.
    s.single.set_hint(s.seed_count > 0 ? s.seeds[0] : kNoTriangle);
    hits[0] = s.single.closest(queries[0], counters);
    s.seeds[0] = hits[0].triangle;
    s.seed_count = 1;
    return 1;
  }
  g.scale = std::max({g.scale, s.fine.scale, s.has_coarse ? s.coarse.scale : 0.0});
  if (!box_filter_usable(g.scale)) {
    for (std::size_t k = 0; k < n; ++k) hits[k] = s.single.closest(queries[k], counters);
    s.seed_count = 0;
    return n;
  }
  g.margin = kSearchMarginScale * g.scale;
  s.next_epoch();
  if (s.seed_count == 0) {
    s.single.forget();
    s.seeds[0] = s.single.closest(queries[0], counters).triangle;
    s.seed_count = 1;
  }
  // The first seed on every lane makes every bound finite; the others are checked by box.
  for (std::size_t k = 0; k < s.seed_count; ++k) {
    const std::uint32_t t = s.seeds[k];
    s.stamps[t] = s.epoch;
    ++counters.triangles_considered;
    measure(g, s.triangles[t], t, k == 0, counters);
  }
  update_group_bound(g);

  const bool far = s.has_coarse && std::sqrt(g.group_bound_sq) - g.margin > s.far_from;
  const GroupLevel& level = far ? s.coarse : s.fine;
  for (int axis = 0; axis < 3; ++axis) {
    // Any start cells give the exact result (the stopping rule reads exact bounds), so the
    // product by the inverse serves.
    const double last = static_cast<double>(level.last_cell[axis]);
    g.first[axis] = static_cast<std::int64_t>(
        std::clamp((g.lo[axis] - level.origin[axis]) * level.inverse_cell, 0.0, last));
    g.last[axis] = static_cast<std::int64_t>(
        std::clamp((g.hi[axis] - level.origin[axis]) * level.inverse_cell, 0.0, last));
  }
  s.candidates.clear();
  for (std::int64_t m = 0;; ++m) {
    for (int axis = 0; axis < 3; ++axis) {
      g.seen_lo[axis] = std::max<std::int64_t>(0, g.first[axis] - m);
      g.seen_hi[axis] = std::min(level.last_cell[axis], g.last[axis] + m);
    }
    const std::size_t from = s.candidates.size();
    gather_shell(s, level, g, m, counters);
    measure_candidates(s, g, from, counters);
    if (covers_grid(level, g) || unvisited_squared_distance(level, g) > g.group_bound_sq) break;
  }

  for (std::size_t k = 0; k < n; ++k) {
    hits[k].squared_distance = g.best_sq[k];
    hits[k].point = Vec3(g.best_x[k], g.best_y[k], g.best_z[k]);
    hits[k].triangle = static_cast<std::uint32_t>(g.best_t[k]);
    hits[k].feature = static_cast<TriangleFeature>(g.best_f[k]);
  }
  // The next group begins where this one ends: its last points' triangles first.
  s.seed_count = 0;
  for (std::size_t k = n; k-- > 0 && s.seed_count < kGroupSeeds;) {
    const auto seeds_end = s.seeds.begin() + static_cast<std::ptrdiff_t>(s.seed_count);
    if (std::find(s.seeds.begin(), seeds_end, hits[k].triangle) == seeds_end) {
      s.seeds[s.seed_count++] = hits[k].triangle;
    }
  }
  return n;
}

}  // namespace
}  // namespace ncv
