// Closes a height field into a watertight solid: the RTIN of the heights on top, vertical
// side walls down to a floor plane, and a flat bottom. The bottom is an RTIN too, refined only
// as far as the top's border samples force it, so walls meet top and bottom edge to edge.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"
#include "ncgen/grid.hpp"

namespace ncv::gen {

// `errors` are propagated RTIN errors of `heights` (see rtin.hpp). Every height must lie
// above floor_z. The solid is outward-oriented.
ncv::Mesh height_field_solid(const Grid& grid, const std::vector<float>& heights,
                             const std::vector<float>& errors, float tolerance, double floor_z);

}  // namespace ncv::gen
