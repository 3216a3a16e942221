// Views of mesh arrays as flat numbers, and back: how meshes and points are stored in
// ncverify files (V×3 doubles, T×3 uint32).
#pragma once

#include <span>
#include <vector>

#include "mesh.hpp"

namespace ncv {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Triangle) == 3 * sizeof(std::uint32_t));

inline std::span<const double> flat_coordinates(std::span<const Vec3> points) {
  return {reinterpret_cast<const double*>(points.data()), points.size() * 3};
}

inline std::span<const std::uint32_t> flat_indices(const std::vector<Triangle>& triangles) {
  return {reinterpret_cast<const std::uint32_t*>(triangles.data()), triangles.size() * 3};
}

template <class Points = std::vector<Vec3>>
Points to_points(std::span<const double> values) {
  Points points(values.size() / 3);
  for (std::size_t k = 0; k < points.size(); ++k) {
    points[k] = {values[3 * k], values[3 * k + 1], values[3 * k + 2]};
  }
  return points;
}

inline std::vector<Triangle> to_triangles(const std::vector<std::uint32_t>& values) {
  std::vector<Triangle> triangles(values.size() / 3);
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    triangles[k] = {values[3 * k], values[3 * k + 1], values[3 * k + 2]};
  }
  return triangles;
}

}  // namespace ncv
