// A sample grid over a rectangle from the origin, made of square tiles of 2^level cells that share
// their border samples. Right-triangulated irregular networks need power-of-two squares; tiling
// them keeps the part's aspect ratio (a 120 x 80 mm block is 3 x 2 tiles).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace ncv::gen {

struct Grid {
  int tiles_x = 1;
  int tiles_y = 1;
  int level = 8;
  double spacing = 1.0;

  int tile_cells() const { return 1 << level; }
  int cells_x() const { return tiles_x << level; }
  int cells_y() const { return tiles_y << level; }
  int samples_x() const { return cells_x() + 1; }
  int samples_y() const { return cells_y() + 1; }
  std::size_t sample_count() const {
    return static_cast<std::size_t>(samples_x()) * static_cast<std::size_t>(samples_y());
  }
  std::uint32_t index(int i, int j) const {
    return static_cast<std::uint32_t>(j) * static_cast<std::uint32_t>(samples_x()) +
           static_cast<std::uint32_t>(i);
  }
  bool contains(int i, int j) const { return i >= 0 && j >= 0 && i <= cells_x() && j <= cells_y(); }
  double x(int i) const { return i * spacing; }
  double y(int j) const { return j * spacing; }
  // Index of the sample nearest a coordinate along either axis.
  int nearest(double coordinate) const {
    return static_cast<int>(std::lround(coordinate / spacing));
  }
};

// The grid covering [0, tiles_x * tile_size] x [0, tiles_y * tile_size] at 2^level cells per
// tile.
inline Grid tiled_grid(int tiles_x, int tiles_y, double tile_size, int level) {
  return Grid{tiles_x, tiles_y, level, tile_size / (1 << level)};
}

}  // namespace ncv::gen
