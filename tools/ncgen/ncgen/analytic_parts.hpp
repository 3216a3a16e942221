// Parts whose deviation from a nominal box is known exactly, for testing the verifier:
// boxes and a box whose top a ball-end cutter has left scallops on.
#pragma once

#include <vector>

#include "mesh/mesh.hpp"

namespace ncv::gen {

// Axis-aligned box, 12 triangles, outward-oriented.
ncv::Mesh box_mesh(Vec3 min, Vec3 max);

// Scallop height a ball end of `radius` leaves between passes `stepover` apart on a plane.
double scallop_height(double radius, double stepover);

// The box [0, size] whose top has been cut by ball-end passes along x at y = 0, s, 2s, ...
// that touch z = size.z: arcs between passes rise to scallop_height at the cusps, so the
// deviation from the box is in [0, scallop_height]. Each half arc is `segments` chords long
// (chords lie above the arc, by at most radius * (1 - cos(half chord angle))). Requires
// stepover <= 2 radius.
ncv::Mesh scalloped_box(Vec3 size, double radius, double stepover, int segments);

// The box [0, size] with a groove along x cut into its top: `width` wide, centred on y =
// centre_y, `depth` deep (depth < 0 raises a rib of that height instead). The groove's walls
// are vertical: the front and back faces get zero-area slivers where a wall meets them, as
// CAD exports do; the surface stays closed and manifold.
ncv::Mesh grooved_box(Vec3 size, double centre_y, double width, double depth);

// The plain box [0, size] with its top split along x at the given y values: the uncut part
// of a grooved box, tessellated so that its samples include those lines.
ncv::Mesh box_with_top_lines(Vec3 size, const std::vector<double>& lines_y);

}  // namespace ncv::gen
