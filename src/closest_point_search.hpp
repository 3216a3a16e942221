// Closest nominal triangle of a query point: over the background grid, and by brute force
// as the reference. Both run the same kernel (closest_point_on_triangle) and break ties
// the same way (the lower triangle index wins), so they return bit-identical results.
//
// Grid search (paper §3.3): start in the query's cell (the nearest cell for a query outside
// the grid) and visit shells of cells of growing Chebyshev radius m around it. Within a
// shell, slabs, rows and cells farther from q than the best distance so far are skipped.
// After shell m the visited cells form the box V (clamped to the grid box G); the search
// stops as soon as
//     dist(q, closure(G \ V)) > best + margin,
// computed exactly as the distance to the up to six slabs that make up G \ V.
//
// Why that is exact. Every nominal triangle lies in G, and the builder lists a triangle
// in every cell it touches. Take a triangle not tested yet. Its part inside V lies in
// cells that were skipped, each farther than best + margin when skipped (and best only
// shrinks); its part outside V lies in closure(G \ V), farther than best + margin now. So
// its true distance exceeds best + margin. The margin, 2^-30 of the coordinate scale of
// the query and the grid, exceeds by orders of magnitude the rounding of the kernel and of
// the box distances (a few ulps of that scale), so the kernel's value for that triangle
// is strictly greater than best: it can neither be nearer nor tie, and the result is the
// one brute force finds. (A sliver so thin that the kernel loses more than ~20 bits
// would defeat the margin, and brute force itself would be that far from the truth.)
//
// Each triangle is tested at most once per query (a per-searcher stamp per triangle), and
// nothing is allocated per query: one GridSearch per thread.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "closest_point.hpp"
#include "uniform_grid.hpp"

namespace ncv {

inline constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

struct ClosestHit {
  Vec3 point;  // in the frame of the triangles
  double squared_distance = std::numeric_limits<double>::infinity();
  std::uint32_t triangle = kNoTriangle;
  TriangleFeature feature = TriangleFeature::face;
};

struct SearchCounters {
  std::uint64_t triangles_tested = 0;
  std::uint64_t cells_visited = 0;  // cells whose lists were read
};

// The one ordering of candidates: nearer wins, then the lower triangle index.
inline bool improves(double squared_distance, std::uint32_t triangle, const ClosestHit& best) {
  return squared_distance < best.squared_distance ||
         (squared_distance == best.squared_distance && triangle < best.triangle);
}

ClosestHit brute_force_closest(std::span<const TriangleCorners> triangles, Vec3 q,
                               SearchCounters& counters);

class GridSearch {
 public:
  // The grid must have been built for (or validated against) these triangles.
  GridSearch(std::span<const TriangleCorners> triangles, const UniformGrid& grid);

  ClosestHit closest(Vec3 q, SearchCounters& counters);

 private:
  struct Query;
  void visit_shell(Query& query, std::int64_t m);
  void visit_cell(Query& query, std::uint64_t cell);
  bool covers_grid(const Query& query) const;
  double unvisited_squared_distance(const Query& query) const;

  std::span<const TriangleCorners> triangles_;
  const UniformGrid& grid_;
  BoundingBox box_;
  double scale_ = 0;
  std::vector<std::uint32_t> stamps_;
  std::uint32_t epoch_ = 0;
};

}  // namespace ncv
