// Exact triangle / axis-aligned box overlap test (Akenine-Möller 2001, separating axis
// theorem) in double precision. Touching counts as overlapping. Degenerate triangles
// (segments, points) are handled: their plane test is vacuous and the remaining axes
// separate a segment or a point from a box on their own.
#pragma once

#include "geometry/vec3.hpp"

namespace ncv {

bool triangle_box_overlap(Vec3 box_center, Vec3 box_half_size, Vec3 a, Vec3 b, Vec3 c);

}  // namespace ncv
