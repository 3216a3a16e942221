#include "search/closest_point_search.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

#include "search/box_lanes.hpp"

namespace ncv {
namespace {

double gap(double q, double lo, double hi) {
  return std::max(std::max(lo - q, q - hi), 0.0);
}

// Lanes k of the block starting at reference `first` with begin <= first + k < end.
unsigned cell_lanes(std::uint64_t first, std::uint64_t begin, std::uint64_t end) {
  constexpr unsigned all = (1u << kBoxLanes) - 1;
  unsigned lanes = all;
  if (first < begin) lanes &= all << (begin - first);
  if (end - first < kBoxLanes) lanes &= (1u << (end - first)) - 1;
  return lanes & all;
}

struct Candidate {
  std::uint32_t triangle;
  float squared;  // its box's squared float gap to the query
};

// The candidate whose box is nearest goes first: its triangle is the likeliest to be the
// closest, and once tested, the shrunken bound skips more of the others (on a fine nominal,
// 3.59 -> 2.98 exact tests per sample). A full sort costs more than it saves. The scan
// selects instead of branching: which candidate is nearer is as good as random.
void move_nearest_box_first(Candidate* found, std::size_t count) {
  std::size_t nearest = 0;
  float nearest_squared = count > 0 ? found[0].squared : 0.0f;
  for (std::size_t k = 1; k < count; ++k) {
    const bool nearer = found[k].squared < nearest_squared;
    nearest = nearer ? k : nearest;
    nearest_squared = nearer ? found[k].squared : nearest_squared;
  }
  if (nearest != 0) std::swap(found[0], found[nearest]);
}

}  // namespace

ClosestHit brute_force_closest(MeshCorners triangles, Vec3 q, SearchCounters& counters) {
  ClosestHit best;
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    const TrianglePoint candidate = closest_point_on_triangle(q, triangles[t]);
    if (improves(candidate.squared_distance, t, best)) {
      best = {candidate.point, candidate.squared_distance, t, candidate.feature};
    }
  }
  counters.triangles_tested += triangles.size();
  counters.triangles_considered += triangles.size();
  return best;
}

struct GridSearcher::Query {
  Vec3 q{0, 0, 0};
  std::array<double, 3> at;            // q by axis (Vec3's operator[] costs a branch per access)
  std::array<std::int64_t, 3> centre;  // cell of the query, clamped to the grid
  std::array<std::int64_t, 3> lo, hi;  // visited box, inclusive cell indices
  double scale = 0;                    // coordinate scale of the query and the grid
  double margin = 0;                   // kSearchMarginScale * scale
  double bound_sq = std::numeric_limits<double>::infinity();  // (best + margin)^2
  // The float box prefilter (box_lanes.hpp): the query in float and the bound as a float
  // limit; without it (coordinates out of its range), every box passes.
  bool filter = false;
  float point[3];
  float limit = std::numeric_limits<float>::infinity();
  ClosestHit best;
  SearchCounters* counters = nullptr;
};

GridSearcher::GridSearcher(const SearchIndex& index, GridLevel level)
    : triangles_(index.triangles()),
      grid_(index.grid(level)),
      boxes_(index.boxes(level)),
      stamps_(triangles_.size(), 0) {
  const BoundingBox box = grid_.bounds();
  scale_ = std::max(max_abs(box.min), max_abs(box.max));
  for (int axis = 0; axis < 3; ++axis) {
    origin_[axis] = grid_.origin[axis];
    box_min_[axis] = box.min[axis];
    box_max_[axis] = box.max[axis];
    last_cell_[axis] = std::int64_t{grid_.dims[axis]} - 1;
  }
  inverse_cell_ = 1.0 / grid_.cell_size;
}

ClosestHit GridSearcher::closest(Vec3 q, SearchCounters& counters) {
  if (++epoch_ == 0) {
    std::fill(stamps_.begin(), stamps_.end(), 0);
    epoch_ = 1;
  }
  Query query;
  query.q = q;
  query.at = {q[0], q[1], q[2]};
  query.counters = &counters;
  query.scale = std::max(scale_, max_abs(q));
  query.margin = kSearchMarginScale * query.scale;
  query.filter = box_filter_usable(query.scale);
  for (int axis = 0; axis < 3; ++axis) query.point[axis] = static_cast<float>(query.at[axis]);
  for (int axis = 0; axis < 3; ++axis) {
    // Any start cell gives the exact result (the stopping rule uses the visited box and
    // exact cell bounds), so a product by the inverse is as good as the quotient; clamped
    // first, the index is non-negative and truncation is its floor.
    const double index = (query.at[axis] - origin_[axis]) * inverse_cell_;
    query.centre[axis] =
        static_cast<std::int64_t>(std::clamp(index, 0.0, static_cast<double>(last_cell_[axis])));
  }
  if (hint_ != kNoTriangle) {
    stamps_[hint_] = epoch_;
    ++counters.triangles_considered;
    test(query, hint_);
  }
  // Shell 0 is the start cell alone; visiting it whatever its distance is always safe.
  query.lo = query.centre;
  query.hi = query.centre;
  visit_cell(query, grid_.cell_index(static_cast<std::uint32_t>(query.centre[0]),
                                     static_cast<std::uint32_t>(query.centre[1]),
                                     static_cast<std::uint32_t>(query.centre[2])));
  if (bound_inside_start_cell(query) || covers_grid(query) ||
      unvisited_squared_distance(query) > query.bound_sq) {
    hint_ = query.best.triangle;
    return query.best;
  }
  for (std::int64_t m = 1;; ++m) {
    for (int axis = 0; axis < 3; ++axis) {
      query.lo[axis] = std::max<std::int64_t>(0, query.centre[axis] - m);
      query.hi[axis] = std::min(last_cell_[axis], query.centre[axis] + m);
    }
    visit_shell(query, m);
    if (covers_grid(query) || unvisited_squared_distance(query) > query.bound_sq) break;
  }
  hint_ = query.best.triangle;
  return query.best;
}

// The cells of the clamped box whose Chebyshev distance to the centre cell is m, skipping
// slabs, rows and cells farther than the current bound.
void GridSearcher::visit_shell(Query& query, std::int64_t m) {
  const auto& c = query.centre;
  for (std::int64_t z = query.lo[2]; z <= query.hi[2]; ++z) {
    const double gz = cell_gap(query, 2, z);
    const double gz_sq = gz * gz;
    if (gz_sq > query.bound_sq) continue;
    const bool z_face = z == c[2] - m || z == c[2] + m;
    for (std::int64_t y = query.lo[1]; y <= query.hi[1]; ++y) {
      const double gy = cell_gap(query, 1, y);
      const double gyz_sq = gz_sq + gy * gy;
      if (gyz_sq > query.bound_sq) continue;
      const bool whole_row = z_face || y == c[1] - m || y == c[1] + m;
      const std::int64_t step = whole_row ? 1 : 2 * m;
      for (std::int64_t x = whole_row ? query.lo[0] : c[0] - m; x <= query.hi[0]; x += step) {
        if (x < 0) continue;
        const double gx = cell_gap(query, 0, x);
        if (gyz_sq + gx * gx > query.bound_sq) continue;
        visit_cell(query,
                   grid_.cell_index(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                                    static_cast<std::uint32_t>(z)));
      }
    }
  }
}

// Empty cells return before the scan's set-up: a sample far off the nominal reads mostly
// empty cells (roughing: 9.4 cells per sample; the search is 1.18x faster than when the
// scan's frame was built for every cell).
void GridSearcher::visit_cell(Query& query, std::uint64_t cell) {
  ++query.counters->cells_visited;
  const std::uint64_t begin = grid_.cell_offsets[cell];
  const std::uint64_t end = grid_.cell_offsets[cell + 1];
  query.counters->triangles_considered += end - begin;
  if (begin != end) scan_cell(query, begin, end);
}

// Two passes per chunk of blocks, so that the box tests run without a branch per lane or
// per block: the first measures the blocks and appends every passing lane to `found` (every
// lane is written, the count only advances for passing ones; skipping blocks with none
// mispredicted on dense cells); the second tests those, re-checking each box against the
// bound, which may have shrunk since.
void GridSearcher::scan_cell(Query& query, std::uint64_t begin, std::uint64_t end) {
  constexpr std::size_t kCapacity = 32;
  std::uint64_t first = begin - begin % kBoxLanes;
  while (first < end) {
    Candidate found[kCapacity];
    std::size_t count = 0;
    const LaneQuery near = lane_query(query.point, query.limit);
    for (; first < end && count + kBoxLanes <= kCapacity; first += kBoxLanes) {
      const BoxBlock& block = boxes_[first / kBoxLanes];
      float squared[kBoxLanes] = {0, 0, 0, 0};
      unsigned lanes = cell_lanes(first, begin, end);
      if (query.filter) lanes &= near_lanes(block, near, squared);
      for (int lane = 0; lane < kBoxLanes; ++lane) {
        found[count] = {block.triangle[lane], squared[lane]};
        count += (lanes >> lane) & 1u;
      }
    }
    // The candidates' vertex indices are requested together, so their cache misses overlap.
    for (std::size_t k = 0; k < count; ++k) triangles_.prefetch(found[k].triangle);
    move_nearest_box_first(found, count);
    for (std::size_t k = 0; k < count; ++k) {
      if (found[k].squared > query.limit) continue;
      const std::uint32_t t = found[k].triangle;
      if (stamps_[t] == epoch_) continue;
      stamps_[t] = epoch_;
      test(query, t);
    }
  }
}

void GridSearcher::test(Query& query, std::uint32_t t) {
  ++query.counters->triangles_tested;
  const TrianglePoint candidate = closest_point_on_triangle(query.q, triangles_[t]);
  if (!improves(candidate.squared_distance, t, query.best)) return;
  query.best = {candidate.point, candidate.squared_distance, t, candidate.feature};
  const double bound = std::sqrt(candidate.squared_distance) + query.margin;
  query.bound_sq = bound * bound;
  if (query.filter) query.limit = box_filter_limit(bound, query.scale);
}

// Distance from q to cell slab i along the axis.
double GridSearcher::cell_gap(const Query& query, int axis, std::int64_t i) const {
  return gap(query.at[axis], cell_bound(axis, i), cell_bound(axis, i + 1));
}

// The usual way a search ends: q lies in its start cell (the only cell visited so far) and
// every face of the cell is farther than the bound, so the unvisited part of the grid is
// too. Six differences instead of unvisited_squared_distance's slabs; when it fails (a
// bound reaching out of the cell, or q outside the grid), the exact rule decides.
bool GridSearcher::bound_inside_start_cell(const Query& query) const {
  double nearest_face = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const std::int64_t i = query.centre[axis];
    nearest_face = std::min(nearest_face, query.at[axis] - cell_bound(axis, i));
    nearest_face = std::min(nearest_face, cell_bound(axis, i + 1) - query.at[axis]);
  }
  return nearest_face > 0 && nearest_face * nearest_face > query.bound_sq;
}

bool GridSearcher::covers_grid(const Query& query) const {
  for (int axis = 0; axis < 3; ++axis) {
    if (query.lo[axis] > 0 || query.hi[axis] < last_cell_[axis]) return false;
  }
  return true;
}

// dist^2(q, closure(G \ V)): G \ V is the union of the slabs of G below and above V along
// each axis (those that exist).
double GridSearcher::unvisited_squared_distance(const Query& query) const {
  const auto& q = query.at;
  std::array<double, 3> outside;
  for (int axis = 0; axis < 3; ++axis) {
    const double g = gap(q[axis], box_min_[axis], box_max_[axis]);
    outside[axis] = g * g;
  }
  // Squared distance to the grid box in the two axes other than each one.
  const std::array<double, 3> others{outside[1] + outside[2], outside[2] + outside[0],
                                     outside[0] + outside[1]};
  double nearest = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    if (query.lo[axis] > 0) {
      const double g = gap(q[axis], box_min_[axis], cell_bound(axis, query.lo[axis]));
      nearest = std::min(nearest, others[axis] + g * g);
    }
    if (query.hi[axis] < last_cell_[axis]) {
      const double g = gap(q[axis], cell_bound(axis, query.hi[axis] + 1), box_max_[axis]);
      nearest = std::min(nearest, others[axis] + g * g);
    }
  }
  return nearest;
}

}  // namespace ncv
