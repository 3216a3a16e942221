// Quadric-error decimation of a triangulated height field with OpenMesh's decimater
// (DecimaterT), as many CAM systems reduce the mesh of a milling simulation before export:
// halfedge collapses in the order of Garland and Heckbert's quadric error (ModQuadricT), each
// allowed only if every removed sample stays within a distance of the face above or below it
// (SampleBoundT), the top stays a height field (HeightFieldGuardT) and no vertex gets far more
// edges than a regular mesh (ValenceCapT). Collapses move no vertex, so the result's vertices
// are grid samples still and it comes back as grid triangles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ncgen/grid.hpp"
#include "ncgen/rtin.hpp"

namespace ncv::gen {

struct DecimationOptions {
  std::size_t target = 0;  // triangles wanted; fewer collapses when the tolerance forbids more
  double tolerance = 0;    // mm: every removed sample stays this close (3D) to the surface
};

struct Decimation {
  std::vector<GridTriangle> triangles;  // counter-clockwise seen from +z
  std::size_t collapses = 0;
};

// Decimates `triangles` (counter-clockwise from +z, covering the grid's rectangle once) over
// `heights`. Border samples and the samples in `keep` stay vertices, so the border edges and
// what a closure builds on them do not change. Serial and deterministic: the same input gives
// the same triangles in the same order.
Decimation decimate_height_field(const Grid& grid, const std::vector<float>& heights,
                                 const std::vector<GridTriangle>& triangles,
                                 const std::vector<std::uint32_t>& keep,
                                 const DecimationOptions& options);

}  // namespace ncv::gen
