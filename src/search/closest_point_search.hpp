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
// nothing is allocated per query: one GridSearcher per thread.
//
// Two shortcuts make the bound tight early without changing the result; the result does
// not depend on the order triangles are tested in, since `improves` is a strict total
// order (distance, then index) and every triangle that could win is tested exactly:
//  - The hint. The first triangle tested is the previous query's closest one (consecutive
//    samples are neighbours), so the bound is near its final value before the first cell
//    is read. forget_hint() drops it; the distance step does so at fixed block starts, so
//    the counters do not depend on how blocks are spread over threads.
//  - The box prefilter. Before the exact kernel (and before its stamp is read), a cell-list
//    entry is skipped when its triangle's bounding box is farther from q than the bound
//    best + margin. The boxes are floats rounded outward, stored per reference four to a
//    block (reference_boxes.hpp) and measured four at a time with a conservative float
//    test (box_lanes.hpp): a box is only skipped when its exact distance exceeds the bound,
//    so by the argument above the kernel's value for its triangle would be strictly greater
//    than best: skipping it cannot change the result. A cell's boxes are read contiguously;
//    of the triangles whose boxes pass, the one with the nearest box is tested first.
// SearchCounters::triangles_tested counts exact kernel evaluations only (the paper's
// Table 2 statistic); triangles_considered counts the cell-list entries read (each checked
// against its box; a triangle listed in two visited cells counts twice) plus the hint.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geometry/closest_point.hpp"
#include "mesh/mesh_corners.hpp"
#include "search/background_grid.hpp"
#include "search/reference_boxes.hpp"
#include "search/search_index.hpp"

namespace ncv {

inline constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

// The margin of the stopping rule and of the prefilters, in units of the coordinate scale of
// the query and the grid (see above).
inline constexpr double kSearchMarginScale = 0x1p-30;

struct ClosestHit {
  Vec3 point{0, 0, 0};  // in the frame of the triangles
  double squared_distance = std::numeric_limits<double>::infinity();
  std::uint32_t triangle = kNoTriangle;
  TriangleFeature feature = TriangleFeature::face;
};

struct SearchCounters {
  std::uint64_t triangles_tested = 0;      // exact point-triangle computations
  std::uint64_t triangles_considered = 0;  // cell-list entries read + hint (see above)
  std::uint64_t cells_visited = 0;         // cells whose lists were read
};

// The one ordering of candidates: nearer wins, then the lower triangle index.
inline bool improves(double squared_distance, std::uint32_t triangle, const ClosestHit& best) {
  return squared_distance < best.squared_distance ||
         (squared_distance == best.squared_distance && triangle < best.triangle);
}

ClosestHit brute_force_closest(MeshCorners triangles, Vec3 q, SearchCounters& counters);

class GridSearcher {
 public:
  // `index` is shared by the searchers of all threads and must outlive them; the searcher
  // reads the given level of its grid (the coarse one only where the index has it).
  explicit GridSearcher(const SearchIndex& index, GridLevel level = GridLevel::fine);

  ClosestHit closest(Vec3 q, SearchCounters& counters);
  // The next query starts without the previous one's closest triangle.
  void forget_hint() { hint_ = kNoTriangle; }
  // The next query starts with triangle t instead (a valid index, the result is the same; or
  // kNoTriangle, as forget_hint()).
  void set_hint(std::uint32_t t) { hint_ = t; }

 private:
  struct Query;
  void visit_shell(Query& query, std::int64_t m);
  void visit_cell(Query& query, std::uint64_t cell);
  // The references begin..end (a cell's, not empty).
  void scan_cell(Query& query, std::uint64_t begin, std::uint64_t end);
  void test(Query& query, std::uint32_t t);
  bool bound_inside_start_cell(const Query& query) const;
  bool covers_grid(const Query& query) const;
  // grid_.cell_bound(axis, i), from the origin copied into the searcher.
  double cell_bound(int axis, std::int64_t i) const {
    return ncv::cell_bound(origin_[axis], grid_.cell_size, i);
  }
  double cell_gap(const Query& query, int axis, std::int64_t i) const;
  double unvisited_squared_distance(const Query& query) const;

  MeshCorners triangles_;
  const BackgroundGrid& grid_;
  std::span<const BoxBlock> boxes_;
  // The grid's origin, box and last cell index by axis.
  std::array<double, 3> origin_, box_min_, box_max_;
  std::array<std::int64_t, 3> last_cell_;
  double scale_ = 0;
  double inverse_cell_ = 0;
  std::vector<std::uint32_t> stamps_;
  std::uint32_t epoch_ = 0;
  std::uint32_t hint_ = kNoTriangle;
};

}  // namespace ncv
