#include "search/search_index.hpp"

#include "search/coarse_grid.hpp"

namespace ncv {

SearchIndex::SearchIndex(const IndexedReference& reference)
    : reference_(&reference),
      boxes_(build_reference_boxes(reference.surface->corners(), reference.grid)) {
  if (reference.grid.cell_triangles.size() <= kMostCoarseReferences) {
    coarse_ = coarsen(reference.grid);
    coarse_boxes_ = build_reference_boxes(reference.surface->corners(), *coarse_);
  }
}

}  // namespace ncv
