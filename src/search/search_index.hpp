// What the search reads (closest_point_search.hpp): a reference's triangles, its grid's cell
// lists, and every reference's triangle box, four to a block (reference_boxes.hpp). It is made
// from an IndexedReference only, which owns both the triangles and the grid, so a search
// cannot pair boxes or cells with another surface's triangles.
//
// The boxes depend on the reference and its grid only, so they are built once per reference,
// where the grid is built or read, and shared by the searchers of every thread: the distance
// step's cost is then per sample only (on a 1.6 M-triangle nominal the boxes are 69 MB, and
// building them costs as much as searching a few hundred thousand samples).
#pragma once

#include <span>

#include "geometry/closest_point.hpp"
#include "search/indexed_reference.hpp"
#include "search/reference_boxes.hpp"
#include "util/buffer.hpp"

namespace ncv {

class SearchIndex {
 public:
  // `reference` must outlive this.
  explicit SearchIndex(const IndexedReference& reference)
      : reference_(&reference),
        boxes_(build_reference_boxes(reference.surface->corners(), reference.grid)) {}

  const ReferenceSurface& surface() const { return *reference_->surface; }
  std::span<const TriangleCorners> triangles() const { return reference_->surface->corners(); }
  const BackgroundGrid& grid() const { return reference_->grid; }
  std::span<const BoxBlock> boxes() const { return boxes_; }

 private:
  const IndexedReference* reference_;
  Buffer<BoxBlock> boxes_;
};

}  // namespace ncv
