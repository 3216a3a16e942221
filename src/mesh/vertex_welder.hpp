// Welds vertex coordinates by exact equality (an STL stores every corner separately).
// Open addressing on the coordinate bits: no per-vertex allocation, first-seen order.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/vec3.hpp"

namespace ncv {

class VertexWelder {
 public:
  explicit VertexWelder(std::size_t expected_vertices);
  // Index of the vertex with these coordinates, adding it if new.
  std::uint32_t weld(Vec3 p);
  // weld(points[i]) into indices[i] for each i, in order; the table is prefetched a few
  // points ahead, since its random accesses, not the arithmetic, are what welding costs.
  void weld_all(std::span<const Vec3> points, std::span<std::uint32_t> indices);
  std::vector<Vec3> take_vertices() { return std::move(vertices_); }

 private:
  std::uint32_t weld(Vec3 p, std::size_t hash);  // hash = hash_bits of p's coordinates
  // p as vertex number vertices_.size(), in the empty slot its probe ended at.
  std::uint32_t insert(Vec3 p, const std::array<std::uint64_t, 3>& bits, std::size_t slot);
  void grow();

  std::vector<std::array<std::uint64_t, 3>> keys_;
  std::vector<std::uint32_t> slots_;  // vertex index + 1, 0 = empty
  std::vector<Vec3> vertices_;
  std::size_t mask_ = 0;
};

}  // namespace ncv
