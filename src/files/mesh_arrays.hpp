// Views of mesh arrays as flat numbers: how meshes and points are stored in ncverify files
// (V×3 doubles, T×3 uint32). Loading copies such sections straight into rows
// (Container::get_rows).
#pragma once

#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace ncv {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Triangle) == 3 * sizeof(std::uint32_t));

inline std::span<const double> flat_coordinates(std::span<const Vec3> points) {
  return {reinterpret_cast<const double*>(points.data()), points.size() * 3};
}

inline std::span<const std::uint32_t> flat_indices(const std::vector<Triangle>& triangles) {
  return {reinterpret_cast<const std::uint32_t*>(triangles.data()), triangles.size() * 3};
}

}  // namespace ncv
