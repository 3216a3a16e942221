#include "search/reference_boxes.hpp"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace ncv {

float float_at_or_below(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                    : f;
}

float float_at_or_above(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

namespace {

BoxBlock empty_block() {
  BoxBlock block{};
  for (int axis = 0; axis < 3; ++axis) {
    std::fill_n(block.lo[axis], kBoxLanes, std::numeric_limits<float>::infinity());
    std::fill_n(block.hi[axis], kBoxLanes, -std::numeric_limits<float>::infinity());
  }
  std::fill_n(block.triangle, kBoxLanes, kPaddingTriangle);
  return block;
}

// A triangle's box in float, rounded outward.
struct FloatBox {
  float lo[3];
  float hi[3];
};

FloatBox float_box(const TriangleCorners& c) {
  const BoundingBox rounded = search_box(c);  // float values already: converted exactly
  FloatBox box;
  for (int axis = 0; axis < 3; ++axis) {
    box.lo[axis] = static_cast<float>(rounded.min[axis]);
    box.hi[axis] = static_cast<float>(rounded.max[axis]);
  }
  return box;
}

void fill_blocks(std::span<const FloatBox> triangle_boxes, const BackgroundGrid& grid,
                 std::span<BoxBlock> blocks, std::size_t begin, std::size_t end) {
  for (std::size_t b = begin; b < end; ++b) {
    BoxBlock& block = blocks[b];
    block = empty_block();
    for (int lane = 0; lane < kBoxLanes; ++lane) {
      const std::size_t r = b * kBoxLanes + static_cast<std::size_t>(lane);
      if (r >= grid.cell_triangles.size()) break;
      const std::uint32_t t = grid.cell_triangles[r];
      const FloatBox& box = triangle_boxes[t];
      block.triangle[lane] = t;
      for (int axis = 0; axis < 3; ++axis) {
        block.lo[axis][lane] = box.lo[axis];
        block.hi[axis][lane] = box.hi[axis];
      }
    }
  }
}

}  // namespace

// Each triangle's box is rounded once, reading the corners in order; the blocks then
// gather the boxes (a third of the corners' size) by reference. Rounding per reference
// read the corners in cell order, which missed the cache about once per reference on a
// large nominal.
BoundingBox search_box(const TriangleCorners& c) {
  BoundingBox box;
  for (int axis = 0; axis < 3; ++axis) {
    box.min[axis] = float_at_or_below(std::min({c[0][axis], c[1][axis], c[2][axis]}));
    box.max[axis] = float_at_or_above(std::max({c[0][axis], c[1][axis], c[2][axis]}));
  }
  return box;
}

Buffer<BoxBlock> build_reference_boxes(MeshCorners triangles, const BackgroundGrid& grid) {
  Buffer<FloatBox> triangle_boxes(triangles.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles.size(), 1 << 14),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t t = range.begin(); t != range.end(); ++t)
                        triangle_boxes[t] = float_box(triangles[t]);
                    });
  Buffer<BoxBlock> blocks((grid.cell_triangles.size() + kBoxLanes - 1) / kBoxLanes);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size(), 1 << 12),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      fill_blocks(triangle_boxes, grid, blocks, range.begin(), range.end());
                    });
  return blocks;
}

}  // namespace ncv
