// Welds vertex coordinates by exact equality, one at a time (an ASCII STL stores every corner
// separately; binary STL is welded in parallel by mesh/facet_weld.hpp, to the same mesh).
// Open addressing on the coordinate bits: no per-vertex allocation, first-seen order.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "geometry/vec3.hpp"

namespace ncv {

class VertexWelder {
 public:
  explicit VertexWelder(std::size_t expected_vertices);
  // Index of the vertex with these coordinates, adding it if new.
  std::uint32_t weld(Vec3 p);
  std::vector<Vec3> take_vertices() { return std::move(vertices_); }

 private:
  void grow();

  std::vector<std::array<std::uint64_t, 3>> keys_;
  std::vector<std::uint32_t> slots_;  // vertex index + 1, 0 = empty
  std::vector<Vec3> vertices_;
  std::size_t mask_ = 0;
};

}  // namespace ncv
