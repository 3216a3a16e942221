// What the search reads (closest_point_search.hpp): a reference's triangles, its grid's cell
// lists, and every reference's triangle box, four to a block (reference_boxes.hpp). It is made
// from an IndexedReference only, which owns both the triangles and the grid, so a search
// cannot pair boxes or cells with another surface's triangles.
//
// The boxes depend on the reference and its grid only, so they are built once per reference,
// where the grid is built or read, and shared by the searchers of every thread: the distance
// step's cost is then per sample only (on a 1.6 M-triangle nominal the boxes are 69 MB, and
// building them costs as much as searching a few hundred thousand samples).
//
// A reference of at most kMostCoarseReferences references also gets the coarse level
// (coarse_grid.hpp) and its boxes, for queries far from it; a larger one (a workpiece indexed
// for the reverse direction, whose samples nearly all lie near it) would pay tens of MB for it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "geometry/closest_point.hpp"
#include "search/indexed_reference.hpp"
#include "search/reference_boxes.hpp"
#include "util/buffer.hpp"

namespace ncv {

enum class GridLevel { fine, coarse };

inline constexpr std::uint64_t kMostCoarseReferences = std::uint64_t{1} << 20;
inline constexpr double kMostGroupedReferences = 12;

class SearchIndex {
 public:
  // `reference` must outlive this.
  explicit SearchIndex(const IndexedReference& reference);

  const IndexedReference& reference() const { return *reference_; }
  const ReferenceSurface& surface() const { return *reference_->surface; }
  MeshCorners triangles() const { return reference_->surface->corners(); }
  const BackgroundGrid& grid() const { return reference_->grid; }
  std::span<const BoxBlock> boxes() const { return boxes_; }

  bool has_coarse_level() const { return coarse_.has_value(); }

  // Whether runs of nearby queries are searched faster together (group_search.hpp) than one
  // by one: where the grid's cells that hold triangles hold few, kMostGroupedReferences a
  // cell on average. A group's box spans about a cell and meets about that many triangles;
  // every one it cannot rule out by box is measured on a vector of points. Measured, the
  // distance step, one thread, ns a sample, groups / one by one: 17 k nominal (6.3 a cell)
  // 81 / 125, 175 k (7.5) 172 / 203, 968 k (10.4) 307 / 310, the finishing workpiece as
  // the reverse direction's reference (19.1) 0.30 / 0.20 s (docs/PERFORMANCE.md).
  bool groups_pay() const { return groups_pay_; }
  // The level's grid and boxes; the coarse one only when has_coarse_level().
  const BackgroundGrid& grid(GridLevel level) const {
    return level == GridLevel::fine ? grid() : *coarse_;
  }
  std::span<const BoxBlock> boxes(GridLevel level) const {
    return level == GridLevel::fine ? boxes() : coarse_boxes_;
  }

 private:
  const IndexedReference* reference_;
  Buffer<BoxBlock> boxes_;
  bool groups_pay_ = false;
  std::optional<BackgroundGrid> coarse_;
  Buffer<BoxBlock> coarse_boxes_;
};

}  // namespace ncv
