// Axis-aligned bounding box.
#pragma once

#include <limits>
#include <span>

#include "geometry/vec3.hpp"

namespace ncv {

struct BoundingBox {
  Vec3 min{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity()};
  Vec3 max{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           -std::numeric_limits<double>::infinity()};

  bool empty() const { return min[0] > max[0]; }
  void extend(Vec3 p) {
    min = component_min(min, p);
    max = component_max(max, p);
  }
  void extend(const BoundingBox& other) {
    min = component_min(min, other.min);
    max = component_max(max, other.max);
  }
  Vec3 center() const { return 0.5 * (min + max); }
  Vec3 extent() const { return max - min; }
  double diagonal() const { return empty() ? 0.0 : norm(max - min); }

  static BoundingBox of(std::span<const Vec3> points) {
    BoundingBox box;
    for (const Vec3& p : points) box.extend(p);
    return box;
  }
};

// Gap between two boxes (0 when they overlap).
inline double box_gap(const BoundingBox& a, const BoundingBox& b) {
  Vec3 gap{0, 0, 0};
  for (int axis = 0; axis < 3; ++axis) {
    gap[axis] = std::max({0.0, a.min[axis] - b.max[axis], b.min[axis] - a.max[axis]});
  }
  return norm(gap);
}

}  // namespace ncv
