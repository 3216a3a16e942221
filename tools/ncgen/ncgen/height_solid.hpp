// Closes a height field into a watertight solid: a triangulation of the heights on top (the
// RTIN, or any other whose vertices are grid samples), vertical side walls down to a floor
// plane, and a flat bottom. The bottom is an RTIN too, refined only as far as the top's border
// samples force it, so walls meet top and bottom edge to edge.
#pragma once

#include <cstddef>
#include <vector>

#include "mesh/mesh.hpp"
#include "ncgen/grid.hpp"
#include "ncgen/rtin.hpp"

namespace ncv::gen {

// `errors` are propagated RTIN errors of `heights` (see rtin.hpp). Every height must lie
// above floor_z. The solid is outward-oriented.
ncv::Mesh height_field_solid(const Grid& grid, const std::vector<float>& heights,
                             const std::vector<float>& errors, float tolerance, double floor_z);

// The same for any top triangulation of grid samples, counter-clockwise seen from +z, that
// covers the grid's rectangle once and whose boundary edges join consecutive border samples
// (an RTIN's does; so does a decimation of it that keeps its border vertices).
ncv::Mesh close_height_field(const Grid& grid, const std::vector<float>& heights,
                             const std::vector<GridTriangle>& top, double floor_z);

// Triangles the walls and bottom add to `top` in close_height_field: a triangle budget for the
// whole solid minus this is the top's.
std::size_t closure_triangle_count(const Grid& grid, const std::vector<GridTriangle>& top);

}  // namespace ncv::gen
