// Right-triangulated irregular network (Evans, Kirkpatrick & Townsend) over a tiled Grid,
// with the bottom-up error propagation of mapbox/martini. Every sample that is not a tile
// corner is the hypotenuse midpoint of one diamond of bintree triangles; a triangle is split
// when its midpoint's error exceeds the tolerance.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ncgen/grid.hpp"

namespace ncv::gen {

using GridTriangle = std::array<std::uint32_t, 3>;

// Distance from each surface sample to the hypotenuse chord it splits, measured in 3D: on a
// steep chord a height difference means less deviation, as for a CAD chord tolerance.
std::vector<float> chord_errors(const Grid& grid, const std::vector<float>& heights);

// Raises every sample's error to the largest among its bintree descendants. Errors then never
// grow downwards, so the samples above any tolerance form a closed split set and the
// triangulation has no cracks, also across tile borders.
void propagate_errors(const Grid& grid, std::vector<float>& errors);

// The RTIN for propagated errors: grid sample indices, counter-clockwise seen from +z.
std::vector<GridTriangle> rtin_triangles(const Grid& grid, const std::vector<float>& errors,
                                         float tolerance);

// How many triangles rtin_triangles would return, without building them.
std::size_t rtin_triangle_count(const Grid& grid, const std::vector<float>& errors,
                                float tolerance);

// A tolerance at which the RTIN has about `target` triangles.
float tolerance_for_count(const Grid& grid, const std::vector<float>& errors, std::size_t target);

}  // namespace ncv::gen
