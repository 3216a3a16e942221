#include "ncgen/nominal_part.hpp"

#include <tbb/parallel_for.h>

#include <cmath>
#include <stdexcept>

#include "ncgen/height_solid.hpp"
#include "ncgen/rtin.hpp"

namespace ncv::gen {

Grid part_grid(const MouldCore& part, int level) {
  const double tiles_x = part.length / tile_size;
  const double tiles_y = part.width / tile_size;
  if (tiles_x != std::round(tiles_x) || tiles_y != std::round(tiles_y)) {
    throw std::invalid_argument("part sides must be multiples of the RTIN tile size");
  }
  return tiled_grid(static_cast<int>(tiles_x), static_cast<int>(tiles_y), tile_size, level);
}

std::vector<float> sample_heights(const Grid& grid, const MouldCore& part) {
  std::vector<float> heights(grid.sample_count());
  tbb::parallel_for(0, grid.samples_y(), [&](int j) {
    for (int i = 0; i < grid.samples_x(); ++i) {
      heights[grid.index(i, j)] = static_cast<float>(part.height(grid.x(i), grid.y(j)));
    }
  });
  return heights;
}

ncv::Mesh nominal_mesh(const MouldCore& part, const NominalOptions& options) {
  const Grid grid = part_grid(part, options.level);
  const std::vector<float> heights = sample_heights(grid, part);
  std::vector<float> errors = chord_errors(grid, heights);
  propagate_errors(grid, errors);
  return height_field_solid(grid, heights, errors, static_cast<float>(options.chord_tolerance),
                            0.0);
}

}  // namespace ncv::gen
