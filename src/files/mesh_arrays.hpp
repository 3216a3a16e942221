// A mesh's triangles as flat numbers, as ncverify files store them (T×3 uint32); loading
// copies such sections straight into rows (Container::get_rows). Points are stored by
// ContainerWriter::add_points.
#pragma once

#include <span>
#include <vector>

#include "mesh/mesh.hpp"

namespace ncv {

static_assert(sizeof(Vec3) == 3 * sizeof(double) && sizeof(Triangle) == 3 * sizeof(std::uint32_t));

inline std::span<const std::uint32_t> flat_indices(const std::vector<Triangle>& triangles) {
  return {reinterpret_cast<const std::uint32_t*>(triangles.data()), triangles.size() * 3};
}

}  // namespace ncv
