// Distances between two triangles, for the certified bounds (docs/CERTIFICATION.md): a
// lower bound on the least distance between a workpiece patch and a reference triangle,
// which proves that the patch does not touch the reference surface (so the sign of the
// error cannot change inside it) and bounds the error's magnitude from below.
//
// Two disjoint triangles are nearest at a vertex of one and the face of the other, or at
// an edge of each (Ericson, "Real-Time Collision Detection", 5.1.9 and 4.4): the least of
// those 6 vertex-triangle and 9 segment-segment distances is their distance. Disjointness
// is shown by a separating axis (the two face normals, the 9 edge-edge cross products and
// the 6 in-plane edge normals); where none separates the triangles by more than the
// rounding slack, they may touch and the bound is 0.
#pragma once

#include "geometry/closest_point.hpp"

namespace ncv {

// Squared distance between the segments [p1, q1] and [p2, q2] (either may have length 0).
double segment_squared_distance(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2);

// True when some axis separates the triangles by more than `slack` (a length): they are
// then at least that far apart. False says only that no tested axis showed a gap.
bool triangles_separated(const TriangleCorners& a, const TriangleCorners& b, double slack);

// A lower bound on the distance between the triangles, 0 when they may touch. `slack`
// bounds the rounding of the kernels on the coordinates at hand (docs/CERTIFICATION.md).
double triangle_distance_lower_bound(const TriangleCorners& a, const TriangleCorners& b,
                                     double slack);

}  // namespace ncv
