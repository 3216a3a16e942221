#include "search/coarse_grid.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

#include "util/parallel_over.hpp"

namespace ncv {
namespace {

// The fine cells' lists of coarse cell c merged into `out` (cleared first), ascending, each
// triangle once.
void merged_list(const BackgroundGrid& fine, const BackgroundGrid& coarse, std::uint64_t c,
                 std::vector<std::uint32_t>& out) {
  out.clear();
  const std::uint32_t i = static_cast<std::uint32_t>(c % coarse.dims[0]);
  const std::uint32_t j = static_cast<std::uint32_t>(c / coarse.dims[0] % coarse.dims[1]);
  const std::uint32_t k = static_cast<std::uint32_t>(c / coarse.dims[0] / coarse.dims[1]);
  for (std::uint32_t z = 2 * k; z < std::min(2 * k + 2, fine.dims[2]); ++z) {
    for (std::uint32_t y = 2 * j; y < std::min(2 * j + 2, fine.dims[1]); ++y) {
      for (std::uint32_t x = 2 * i; x < std::min(2 * i + 2, fine.dims[0]); ++x) {
        const std::uint64_t cell = fine.cell_index(x, y, z);
        out.insert(out.end(), fine.cell_triangles.begin() + fine.cell_offsets[cell],
                   fine.cell_triangles.begin() + fine.cell_offsets[cell + 1]);
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace

BackgroundGrid coarsen(const BackgroundGrid& fine) {
  BackgroundGrid coarse;
  coarse.origin = fine.origin;
  coarse.cell_size = 2 * fine.cell_size;
  for (int axis = 0; axis < 3; ++axis) coarse.dims[axis] = (fine.dims[axis] + 1) / 2;
  const std::uint64_t cells = coarse.cell_count();
  // The lists' sizes, then their offsets, then the lists at them (each cell merged twice:
  // cheaper than holding every merged list).
  coarse.cell_offsets.resize(cells + 1);
  coarse.cell_offsets[0] = 0;
  parallel_over(cells, 1 << 10, [&](std::size_t c) {
    thread_local std::vector<std::uint32_t> list;
    merged_list(fine, coarse, c, list);
    coarse.cell_offsets[c + 1] = static_cast<std::uint32_t>(list.size());
  });
  std::partial_sum(coarse.cell_offsets.begin(), coarse.cell_offsets.end(),
                   coarse.cell_offsets.begin());
  coarse.cell_triangles.resize(coarse.cell_offsets[cells]);
  parallel_over(cells, 1 << 10, [&](std::size_t c) {
    thread_local std::vector<std::uint32_t> list;
    merged_list(fine, coarse, c, list);
    std::copy(list.begin(), list.end(),
              coarse.cell_triangles.begin() + static_cast<std::ptrdiff_t>(coarse.cell_offsets[c]));
  });
  return coarse;
}

}  // namespace ncv
