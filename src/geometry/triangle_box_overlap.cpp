#include "geometry/triangle_box_overlap.hpp"

#include <algorithm>
#include <cmath>

namespace ncv {
namespace {

// Projections of the (box-centred) corners onto `axis` against the box's projected radius.
bool separated_on(Vec3 axis, Vec3 half, Vec3 v0, Vec3 v1, Vec3 v2) {
  const double p0 = dot(axis, v0);
  const double p1 = dot(axis, v1);
  const double p2 = dot(axis, v2);
  const double radius =
      half[0] * std::fabs(axis[0]) + half[1] * std::fabs(axis[1]) + half[2] * std::fabs(axis[2]);
  return std::min({p0, p1, p2}) > radius || std::max({p0, p1, p2}) < -radius;
}

// The nine axes edge x box-axis: a triangle and a box whose projections are disjoint on one
// of them do not meet even when all face axes overlap.
bool separated_on_edge_axes(Vec3 half, Vec3 v0, Vec3 v1, Vec3 v2) {
  const Vec3 edges[3] = {v1 - v0, v2 - v1, v0 - v2};
  const Vec3 box_axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const Vec3& edge : edges) {
    for (const Vec3& box_axis : box_axes) {
      if (separated_on(cross(box_axis, edge), half, v0, v1, v2)) return true;
    }
  }
  return false;
}

bool separated_on_box_axes(Vec3 half, Vec3 v0, Vec3 v1, Vec3 v2) {
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = std::min({v0[axis], v1[axis], v2[axis]});
    const double hi = std::max({v0[axis], v1[axis], v2[axis]});
    if (lo > half[axis] || hi < -half[axis]) return true;
  }
  return false;
}

// The triangle's plane misses the box when every box corner lies strictly on one side.
bool separated_by_plane(Vec3 half, Vec3 v0, Vec3 v1, Vec3 v2) {
  const Vec3 normal = cross(v1 - v0, v2 - v0);
  const double offset = dot(normal, v0);
  const double radius = half[0] * std::fabs(normal[0]) + half[1] * std::fabs(normal[1]) +
                        half[2] * std::fabs(normal[2]);
  return std::fabs(offset) > radius;
}

}  // namespace

bool triangle_box_overlap(Vec3 box_center, Vec3 box_half_size, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 v0 = a - box_center;
  const Vec3 v1 = b - box_center;
  const Vec3 v2 = c - box_center;
  if (separated_on_box_axes(box_half_size, v0, v1, v2)) return false;
  if (separated_by_plane(box_half_size, v0, v1, v2)) return false;
  return !separated_on_edge_axes(box_half_size, v0, v1, v2);
}

}  // namespace ncv
