// The background grid as the search reads it (closest_point_search.hpp): the nominal's
// triangles, the grid's cell lists, and every reference's triangle box, four to a block
// (reference_boxes.hpp), kept together so a search cannot pair boxes with another grid.
//
// The boxes depend on the nominal and its grid only, so they are built once per nominal,
// where the grid is built or read, and shared by the searchers of every thread: the
// distance step's cost is then per sample only (on a 1.6 M-triangle nominal the boxes are
// 69 MB, and building them costs as much as searching a few hundred thousand samples).
#pragma once

#include <span>

#include "geometry/closest_point.hpp"
#include "search/background_grid.hpp"
#include "search/reference_boxes.hpp"
#include "util/buffer.hpp"

namespace ncv {

class SearchIndex {
 public:
  // `grid` must have been built for (or validated against) `triangles`; both must outlive
  // this.
  SearchIndex(std::span<const TriangleCorners> triangles, const BackgroundGrid& grid)
      : triangles_(triangles), grid_(&grid), boxes_(build_reference_boxes(triangles, grid)) {}

  std::span<const TriangleCorners> triangles() const { return triangles_; }
  const BackgroundGrid& grid() const { return *grid_; }
  std::span<const BoxBlock> boxes() const { return boxes_; }

 private:
  std::span<const TriangleCorners> triangles_;
  const BackgroundGrid* grid_;
  Buffer<BoxBlock> boxes_;
};

}  // namespace ncv
