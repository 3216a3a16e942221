#include "ncgen/raster_milling.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncv::gen {
namespace {

int cells(double length, double spacing) {
  return std::max(1, static_cast<int>(std::lround(length / spacing)));
}

// The first multiple of step at or below -margin, and how many multiples reach last+margin.
std::pair<int, int> covering(int last, int margin, int step) {
  const int first = -((margin + step - 1) / step) * step;
  return {first, (last + margin - first) / step + 1};
}

float location(const Grid& grid, const std::vector<float>& surface, int row, int col,
               const Kernel& clearance) {
  float tip = -std::numeric_limits<float>::infinity();
  for (int dy = -clearance.reach; dy <= clearance.reach; ++dy) {
    const int j = row + dy;
    if (j < 0 || j > grid.cells_y()) continue;
    const int w = clearance.half_width[dy + clearance.reach];
    const int i0 = std::max(col - w, 0);
    const int i1 = std::min(col + w, grid.cells_x());
    const float* heights = &surface[grid.index(i0, j)];
    const float* kernel = &clearance.rows[dy + clearance.reach][i0 - col + w];
    for (int n = 0; n <= i1 - i0; ++n) tip = std::max(tip, heights[n] + kernel[n]);
  }
  return tip;
}

void cut_row(const Grid& grid, float* zrow, int j, const RasterPath& path,
             const std::vector<float>& tips, const Kernel& surface) {
  const int first =
      std::max(0, (j - surface.reach - path.first_row + path.row_step - 1) / path.row_step);
  for (int pass = first; pass < path.rows && path.row(pass) <= j + surface.reach; ++pass) {
    const int dy = j - path.row(pass);
    if (dy < -surface.reach || dy > surface.reach) continue;
    const int w = surface.half_width[dy + surface.reach];
    const float* kernel_row = surface.rows[dy + surface.reach].data();
    for (int position = 0; position < path.cols; ++position) {
      const int col = path.col(position);
      const int i0 = std::max(col - w, 0);
      const int i1 = std::min(col + w, grid.cells_x());
      if (i0 > i1) continue;
      const float tip = tips[static_cast<std::size_t>(pass) * path.cols + position];
      const float* kernel = kernel_row + (i0 - col + w);
      float* z = zrow + i0;
      for (int n = 0; n <= i1 - i0; ++n) z[n] = std::min(z[n], tip + kernel[n]);
    }
  }
}

}  // namespace

RasterPath raster_path(const Grid& grid, double reach, double stepover, double feed) {
  RasterPath path;
  const int margin = static_cast<int>(std::ceil(reach / grid.spacing));
  path.row_step = cells(stepover, grid.spacing);
  path.col_step = cells(feed, grid.spacing);
  std::tie(path.first_row, path.rows) = covering(grid.cells_y(), margin, path.row_step);
  std::tie(path.first_col, path.cols) = covering(grid.cells_x(), margin, path.col_step);
  return path;
}

std::vector<float> cutter_locations(const Grid& grid, const std::vector<float>& surface,
                                    const RasterPath& path, const Kernel& clearance) {
  std::vector<float> tips(path.size());
  tbb::parallel_for(0, path.rows, [&](int pass) {
    for (int position = 0; position < path.cols; ++position) {
      tips[static_cast<std::size_t>(pass) * path.cols + position] =
          location(grid, surface, path.row(pass), path.col(position), clearance);
    }
  });
  return tips;
}

void cut(const Grid& grid, std::vector<float>& zmap, const RasterPath& path,
         const std::vector<float>& tips, const Kernel& surface) {
  tbb::parallel_for(tbb::blocked_range<int>(0, grid.samples_y()),
                    [&](const tbb::blocked_range<int>& rows) {
                      for (int j = rows.begin(); j < rows.end(); ++j) {
                        cut_row(grid, &zmap[grid.index(0, j)], j, path, tips, surface);
                      }
                    });
}

}  // namespace ncv::gen
