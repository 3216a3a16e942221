// The grid's cell lists as the search reads them: every reference (an entry of
// grid.cell_triangles) with its triangle's bounding box in float, rounded outward so that
// the box contains the triangle. References are packed four to a block, structure of
// arrays inside the block (meshoptimizer-style plain data), so that one 4-lane vector
// operation measures four boxes at once; reference r is lane r % 4 of block r / 4, in the
// order of grid.cell_triangles. A cell's references are contiguous but need not start a
// block: the search masks the lanes outside the cell (see box_lanes.hpp). The lanes after
// the last reference hold kPaddingTriangle and an empty box.
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geometry/bounding_box.hpp"
#include "geometry/closest_point.hpp"
#include "mesh/mesh_corners.hpp"
#include "search/background_grid.hpp"
#include "util/buffer.hpp"

namespace ncv {

inline constexpr int kBoxLanes = 4;
inline constexpr std::uint32_t kPaddingTriangle = std::numeric_limits<std::uint32_t>::max();

struct alignas(16) BoxBlock {
  float lo[3][kBoxLanes];  // lo[axis][lane]
  float hi[3][kBoxLanes];
  std::uint32_t triangle[kBoxLanes];
};

// Float bounds that contain [x, x] for any double x: the nearest float, moved one step
// outward when rounding went inward.
float float_at_or_below(double x);
float float_at_or_above(double x);

// A triangle's box as the search stores it: its corners' bounds rounded outward to floats, so
// it holds the triangle and no point of the triangle is nearer than it.
BoundingBox search_box(const TriangleCorners& corners);

// Built in parallel; `grid` must have been built for (or validated against) `triangles`.
Buffer<BoxBlock> build_reference_boxes(MeshCorners triangles, const BackgroundGrid& grid);

}  // namespace ncv
