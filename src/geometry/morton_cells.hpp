// Cells of a bounding box numbered in Morton order: 2^bits cells an axis, a cell's number the
// interleaved bits of its three cell coordinates. Points numbered by their cell come out
// neighbour after neighbour: the vertices of a file whose facets are shuffled
// (mesh/vertex_order.hpp) and the triangles a sample set is measured in
// (sampling/measuring_order.hpp) are put in this order.
#pragma once

#include <algorithm>
#include <cstdint>

#include "geometry/bounding_box.hpp"

namespace ncv {

class MortonCells {
 public:
  // 2^bits cells an axis, bits in 1..10.
  MortonCells(const BoundingBox& box, int bits)
      : low_(box.min),
        extent_(box.max - box.min),
        last_cell_(double((1u << bits) - 1)),
        count_(std::uint32_t{1} << (3 * bits)) {}

  // The number of p's cell, below count(); points outside the box count in its nearest cell,
  // a flat axis has one cell.
  std::uint32_t cell(const Vec3& p) const {
    std::uint64_t code = 0;
    for (int axis = 0; axis < 3; ++axis) {
      code |= spread_bits(cell_of(p[axis], low_[axis], extent_[axis])) << axis;
    }
    return static_cast<std::uint32_t>(code);
  }
  std::uint32_t count() const { return count_; }

 private:
  // The low 21 bits of x spread to every third bit.
  static std::uint64_t spread_bits(std::uint64_t x) {
    x &= 0x1FFFFF;
    x = (x | x << 32) & 0x1F00000000FFFFull;
    x = (x | x << 16) & 0x1F0000FF0000FFull;
    x = (x | x << 8) & 0x100F00F00F00F00Full;
    x = (x | x << 4) & 0x10C30C30C30C30C3ull;
    x = (x | x << 2) & 0x1249249249249249ull;
    return x;
  }

  std::uint64_t cell_of(double x, double low, double extent) const {
    if (!(extent > 0)) return 0;
    return static_cast<std::uint64_t>(std::clamp((x - low) / extent * last_cell_, 0.0, last_cell_));
  }

  Vec3 low_, extent_;
  double last_cell_;
  std::uint32_t count_;
};

}  // namespace ncv
