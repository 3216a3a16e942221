#include "search/search_index.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "search/coarse_grid.hpp"

namespace ncv {
namespace {

std::uint64_t occupied_cells(const BackgroundGrid& grid) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::uint64_t>(0, grid.cell_count(), 1 << 16), std::uint64_t{0},
      [&](const tbb::blocked_range<std::uint64_t>& range, std::uint64_t count) {
        for (std::uint64_t c = range.begin(); c < range.end(); ++c) {
          count += grid.cell_offsets[c + 1] != grid.cell_offsets[c];
        }
        return count;
      },
      [](std::uint64_t a, std::uint64_t b) { return a + b; });
}

}  // namespace

SearchIndex::SearchIndex(const IndexedReference& reference)
    : reference_(&reference),
      boxes_(build_reference_boxes(reference.surface->corners(), reference.grid)) {
  const auto occupied = static_cast<double>(occupied_cells(reference.grid));
  groups_pay_ = static_cast<double>(reference.grid.cell_triangles.size()) <=
                kMostGroupedReferences * occupied;
  if (reference.grid.cell_triangles.size() <= kMostCoarseReferences) {
    coarse_ = coarsen(reference.grid);
    coarse_boxes_ = build_reference_boxes(reference.surface->corners(), *coarse_);
  }
}

}  // namespace ncv
