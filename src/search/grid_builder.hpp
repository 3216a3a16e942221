// Building the background grid (paper §3.3) over a nominal surface.
//
// Cells are cubes of edge h over the nominal's bounding box, padded by at least h/100 on
// every side. Each cell lists the triangles that touch it, by the exact separating-axis
// test (triangle_box_overlap) on the cell grown by a slack of 2^-30 of the grid's
// coordinate scale: far below any cell, far above the rounding in the cell bounds, so no
// triangle that touches a cell can be lost to rounding. Lists are ascending.
//
// Cell size: by default the paper's, the edge of the equilateral triangle whose area is the
// mean nominal triangle area, but no coarser than the cell at which the part's box holds
// kLeastDefaultCells cells (8 a side for a cube). A CAD part of a few large faces (a box of 12
// triangles) would otherwise get a handful of cells, each listing most faces, whose boxes
// pass the search's prefilter: on ncgen's prismatic parts (12-44 triangles) 2.0-2.2 exact
// tests a sample against 1.3-1.5 with 512 cells, and each direction's distance step
// 1.07-1.24 times as long. Finer is not better: with 32768 cells the slot part's reverse
// search, whose samples lie up to 10 mm inside the uncut workpiece, read so many empty cells
// that it took 2.2 times as long as with the paper's 6 cells. GridOptions::cell_size
// overrides the default.
//
// Memory bound, for any input (a CAD mesh mixing a few huge triangles with many tiny ones
// makes the mean-area cell tiny against the huge ones). With T triangles the grid keeps
//   cells      <= max(kCellsPerTriangle * T, kMinCellBudget)
//   references <= max(kReferencesPerTriangle * T, kMinReferenceBudget)
// (a reference is one triangle listed in one cell). While the cell size breaks either
// bound it grows by kGrowth (by the cube root of the cell excess when that is larger).
// References are bounded by counting candidate cells while they are found: those of the
// triangle's bounding box that lie within a few cells of its plane in each column along the
// plane's dominant normal axis (the whole box for a degenerate triangle), and one or two
// cells, untested, where the box spans no more (grid_builder.cpp). The exact test only
// removes candidates, so the bound is strict; an attempt stops as soon as the candidates
// counted exceed the budget, and the cell then grows. The grid then never takes more than
// 4 * 4 T + 4 * 16 T = 80 bytes per triangle (offsets and references of 4 bytes; the
// references stay below 2^32 whatever T), and the build at most 100 bytes per triangle more
// while it runs (the references once more, in per-chunk vectors trimmed when done, and a
// count per triangle), plus one growing chunk of 4096 triangles per thread. Four cells per
// triangle, not more: the search costs the same per query over a wide range of cell sizes
// (0.2 to 1.0 mm measured on a 1.6 M-triangle nominal whose default cell is 0.2 mm), while a
// cell costs an offset of 4 bytes in memory, a count in the grid file and the time to write
// it. At most one exact test per candidate cell. The same bounds apply to a cell size given
// as an option; GridStatistics says when it grew.
//
// Parallel over triangles with oneTBB; the result does not depend on the thread count.
#pragma once

#include <array>
#include <cstdint>

#include "reference/reference_surface.hpp"
#include "search/background_grid.hpp"

namespace ncv {

inline constexpr std::uint64_t kCellsPerTriangle = 4;
inline constexpr std::uint64_t kMinCellBudget = 1 << 15;
inline constexpr std::uint64_t kReferencesPerTriangle = 16;
inline constexpr std::uint64_t kMinReferenceBudget = 1 << 16;
inline constexpr double kGrowth = 1.25;
inline constexpr std::uint64_t kLeastDefaultCells = 512;

struct GridOptions {
  double cell_size = 0;  // model units; 0 = default_cell_size
};

struct GridStatistics {
  std::array<std::uint32_t, 3> dims{0, 0, 0};
  std::uint64_t cells = 0;
  std::uint64_t empty_cells = 0;
  std::uint64_t references = 0;
  double references_per_triangle = 0;
  std::uint64_t max_cell_triangles = 0;
  std::uint64_t bytes = 0;  // of cell_offsets and cell_triangles
  double requested_cell_size = 0;
  double cell_size = 0;
  std::uint32_t growth_steps = 0;  // times the cell size grew to meet the bounds
};

// The paper's cell edge sqrt(4 A / sqrt 3) for the mean triangle area A (for a mesh without
// area, the bounding-box diagonal over the cube root of the triangle count, 1 if that is 0),
// or the smallest edge (to 1 %) at which the grid over the nominal's box has at most
// kLeastDefaultCells cells when that is smaller.
double default_cell_size(const ReferenceSurface& nominal);

// Throws UsageError for a cell size option that is not a finite positive number.
BackgroundGrid build_background_grid(const ReferenceSurface& nominal,
                                     const GridOptions& options = {},
                                     GridStatistics* statistics = nullptr);

}  // namespace ncv
