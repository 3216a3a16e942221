// Raster (zig-zag) milling of a Z-map: pass lines parallel to x, stepped over in y, with
// tool positions at a fixed feed step along each line. Positions lie on grid samples; lines
// and positions run past the grid's edges by the tool's reach so the borders are cut too.
#pragma once

#include <vector>

#include "ncgen/cutter.hpp"
#include "ncgen/grid.hpp"

namespace ncv::gen {

struct RasterPath {
  int first_row = 0;  // grid row of the first pass line (may be negative)
  int row_step = 1;   // stepover in cells
  int rows = 0;
  int first_col = 0;  // grid column of the first position on each line
  int col_step = 1;   // feed step in cells
  int cols = 0;

  int row(int pass) const { return first_row + pass * row_step; }
  int col(int position) const { return first_col + position * col_step; }
  std::size_t size() const { return static_cast<std::size_t>(rows) * cols; }
};

// A path with one pass on grid row 0 whose lines and positions cover the grid plus `reach`
// mm around it. Stepover and feed are rounded to whole cells (at least one).
RasterPath raster_path(const Grid& grid, double reach, double stepover, double feed);

// Tip heights, by pass then position, that keep the cutter at the clearance the kernel
// describes from the surface (a height per grid sample). Positions with no surface within
// reach get -infinity.
std::vector<float> cutter_locations(const Grid& grid, const std::vector<float>& surface,
                                    const RasterPath& path, const Kernel& clearance);

// Lowers the Z-map to the lower envelope of the cutter surface over all path positions.
void cut(const Grid& grid, std::vector<float>& zmap, const RasterPath& path,
         const std::vector<float>& tips, const Kernel& surface);

}  // namespace ncv::gen
