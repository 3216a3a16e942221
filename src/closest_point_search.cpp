#include "closest_point_search.hpp"

#include <algorithm>
#include <cmath>

namespace ncv {
namespace {

constexpr double kMarginScale = 0x1p-30;

double gap(double q, double lo, double hi) {
  return std::max({0.0, lo - q, q - hi});
}

double max_abs(Vec3 v) {
  return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

float round_down(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                    : f;
}

float round_up(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// Squared distance from q to the box, a lower bound of the squared distance to the triangle.
double box_squared_distance(const TriangleBox& box, Vec3 q) {
  const double gx = std::max(std::max(double{box.lo[0]} - q.x, q.x - double{box.hi[0]}), 0.0);
  const double gy = std::max(std::max(double{box.lo[1]} - q.y, q.y - double{box.hi[1]}), 0.0);
  const double gz = std::max(std::max(double{box.lo[2]} - q.z, q.z - double{box.hi[2]}), 0.0);
  return gx * gx + gy * gy + gz * gz;
}

}  // namespace

std::vector<TriangleBox> reference_boxes(std::span<const TriangleCorners> triangles,
                                         const UniformGrid& grid) {
  std::vector<TriangleBox> boxes(grid.cell_triangles.size());
  for (std::size_t r = 0; r < boxes.size(); ++r) {
    const TriangleCorners& c = triangles[grid.cell_triangles[r]];
    for (int axis = 0; axis < 3; ++axis) {
      boxes[r].lo[axis] = round_down(std::min({c[0][axis], c[1][axis], c[2][axis]}));
      boxes[r].hi[axis] = round_up(std::max({c[0][axis], c[1][axis], c[2][axis]}));
    }
  }
  return boxes;
}

ClosestHit brute_force_closest(std::span<const TriangleCorners> triangles, Vec3 q,
                               SearchCounters& counters) {
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

struct GridSearch::Query {
  Vec3 q;
  std::array<std::int64_t, 3> centre{};    // cell of the query, clamped to the grid
  std::array<std::int64_t, 3> lo{}, hi{};  // visited box, inclusive cell indices
  double margin = 0;
  double bound_sq = std::numeric_limits<double>::infinity();  // (best + margin)^2
  ClosestHit best;
  SearchCounters* counters = nullptr;

  double axis_gap(const UniformGrid& grid, int axis, std::int64_t i) const {
    return gap(q[axis], grid.cell_bound(axis, i), grid.cell_bound(axis, i + 1));
  }
};

GridSearch::GridSearch(std::span<const TriangleCorners> triangles, const UniformGrid& grid,
                       std::span<const TriangleBox> boxes)
    : triangles_(triangles),
      grid_(grid),
      boxes_(boxes),
      box_(grid.bounds()),
      stamps_(triangles.size(), 0) {
  scale_ = std::max(max_abs(box_.min), max_abs(box_.max));
  inverse_cell_ = 1.0 / grid.cell_size;
}

ClosestHit GridSearch::closest(Vec3 q, SearchCounters& counters) {
  if (++epoch_ == 0) {
    std::fill(stamps_.begin(), stamps_.end(), 0);
    epoch_ = 1;
  }
  Query query;
  query.q = q;
  query.counters = &counters;
  query.margin = kMarginScale * std::max(scale_, max_abs(q));
  for (int axis = 0; axis < 3; ++axis) {
    // Any start cell gives the exact result (the stopping rule uses the visited box and
    // exact cell bounds), so a product by the inverse is as good as the quotient.
    const double index = std::floor((q[axis] - grid_.origin[axis]) * inverse_cell_);
    query.centre[axis] = static_cast<std::int64_t>(std::clamp(index, 0.0, grid_.dims[axis] - 1.0));
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
  if (covers_grid(query) || unvisited_squared_distance(query) > query.bound_sq) {
    hint_ = query.best.triangle;
    return query.best;
  }
  for (std::int64_t m = 1;; ++m) {
    for (int axis = 0; axis < 3; ++axis) {
      query.lo[axis] = std::max<std::int64_t>(0, query.centre[axis] - m);
      query.hi[axis] = std::min<std::int64_t>(grid_.dims[axis] - 1, query.centre[axis] + m);
    }
    visit_shell(query, m);
    if (covers_grid(query) || unvisited_squared_distance(query) > query.bound_sq) break;
  }
  hint_ = query.best.triangle;
  return query.best;
}

// The cells of the clamped box whose Chebyshev distance to the centre cell is m, skipping
// slabs, rows and cells farther than the current bound.
void GridSearch::visit_shell(Query& query, std::int64_t m) {
  const auto& c = query.centre;
  for (std::int64_t z = query.lo[2]; z <= query.hi[2]; ++z) {
    const double gz = query.axis_gap(grid_, 2, z);
    const double gz_sq = gz * gz;
    if (gz_sq > query.bound_sq) continue;
    const bool z_face = z == c[2] - m || z == c[2] + m;
    for (std::int64_t y = query.lo[1]; y <= query.hi[1]; ++y) {
      const double gy = query.axis_gap(grid_, 1, y);
      const double gyz_sq = gz_sq + gy * gy;
      if (gyz_sq > query.bound_sq) continue;
      const bool whole_row = z_face || y == c[1] - m || y == c[1] + m;
      const std::int64_t step = whole_row ? 1 : 2 * m;
      for (std::int64_t x = whole_row ? query.lo[0] : c[0] - m; x <= query.hi[0]; x += step) {
        if (x < 0) continue;
        const double gx = query.axis_gap(grid_, 0, x);
        if (gyz_sq + gx * gx > query.bound_sq) continue;
        visit_cell(query,
                   grid_.cell_index(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                                    static_cast<std::uint32_t>(z)));
      }
    }
  }
}

void GridSearch::visit_cell(Query& query, std::uint64_t cell) {
  ++query.counters->cells_visited;
  const std::uint64_t end = grid_.cell_offsets[cell + 1];
  query.counters->triangles_considered += end - grid_.cell_offsets[cell];
  for (std::uint64_t r = grid_.cell_offsets[cell]; r < end; ++r) {
    if (box_squared_distance(boxes_[r], query.q) > query.bound_sq) continue;
    const std::uint32_t t = grid_.cell_triangles[r];
    if (stamps_[t] == epoch_) continue;
    stamps_[t] = epoch_;
    test(query, t);
  }
}

void GridSearch::test(Query& query, std::uint32_t t) {
  ++query.counters->triangles_tested;
  const TrianglePoint candidate = closest_point_on_triangle(query.q, triangles_[t]);
  if (!improves(candidate.squared_distance, t, query.best)) return;
  query.best = {candidate.point, candidate.squared_distance, t, candidate.feature};
  const double bound = std::sqrt(candidate.squared_distance) + query.margin;
  query.bound_sq = bound * bound;
}

bool GridSearch::covers_grid(const Query& query) const {
  for (int axis = 0; axis < 3; ++axis) {
    if (query.lo[axis] > 0 || query.hi[axis] < grid_.dims[axis] - 1) return false;
  }
  return true;
}

// dist^2(q, closure(G \ V)): G \ V is the union of the slabs of G below and above V along
// each axis (those that exist).
double GridSearch::unvisited_squared_distance(const Query& query) const {
  std::array<double, 3> outside_sq{};
  for (int axis = 0; axis < 3; ++axis) {
    const double g = gap(query.q[axis], box_.min[axis], box_.max[axis]);
    outside_sq[axis] = g * g;
  }
  double nearest = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const double others = outside_sq[(axis + 1) % 3] + outside_sq[(axis + 2) % 3];
    if (query.lo[axis] > 0) {
      const double g = gap(query.q[axis], box_.min[axis], grid_.cell_bound(axis, query.lo[axis]));
      nearest = std::min(nearest, others + g * g);
    }
    if (query.hi[axis] < grid_.dims[axis] - 1) {
      const double g =
          gap(query.q[axis], grid_.cell_bound(axis, query.hi[axis] + 1), box_.max[axis]);
      nearest = std::min(nearest, others + g * g);
    }
  }
  return nearest;
}

}  // namespace ncv
