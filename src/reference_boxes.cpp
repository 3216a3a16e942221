#include "reference_boxes.hpp"

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

void fill_blocks(std::span<const TriangleCorners> triangles, const UniformGrid& grid,
                 std::span<BoxBlock> blocks, std::size_t begin, std::size_t end) {
  for (std::size_t b = begin; b < end; ++b) {
    BoxBlock& block = blocks[b];
    block = empty_block();
    for (int lane = 0; lane < kBoxLanes; ++lane) {
      const std::size_t r = b * kBoxLanes + static_cast<std::size_t>(lane);
      if (r >= grid.cell_triangles.size()) break;
      const std::uint32_t t = grid.cell_triangles[r];
      const TriangleCorners& c = triangles[t];
      block.triangle[lane] = t;
      for (int axis = 0; axis < 3; ++axis) {
        const double lo = std::min({c[0][axis], c[1][axis], c[2][axis]});
        const double hi = std::max({c[0][axis], c[1][axis], c[2][axis]});
        block.lo[axis][lane] = float_at_or_below(lo);
        block.hi[axis][lane] = float_at_or_above(hi);
      }
    }
  }
}

}  // namespace

Buffer<BoxBlock> build_reference_boxes(std::span<const TriangleCorners> triangles,
                                       const UniformGrid& grid) {
  Buffer<BoxBlock> blocks((grid.cell_triangles.size() + kBoxLanes - 1) / kBoxLanes);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, blocks.size(), 1 << 12),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      fill_blocks(triangles, grid, blocks, range.begin(), range.end());
                    });
  return blocks;
}

}  // namespace ncv
