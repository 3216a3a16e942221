// A mesh's triangles as corner positions, read through its index: the view every distance,
// grid, sign and certification step takes of a reference surface.
//
// It holds no copy. A triangle soup of the corners (72 bytes a triangle) was 86 MB of fresh
// pages for the 1.25 M-triangle workpiece the two-sided run indexes, which this project's
// machines clear and back again at first touch: without it the finishing job's peak fell
// from 481 to 394 MB and its run, a second after the last, from 0.99 to 0.83 s (medians of
// 10), for 2-4 % more time a sample in the search, which now loads the index before the
// corners (docs/PERFORMANCE.md).
#pragma once

#include <cstddef>

#include "geometry/closest_point.hpp"
#include "mesh/mesh.hpp"

namespace ncv {

class MeshCorners {
 public:
  // A view of `mesh`, which must outlive it and keep its arrays unchanged.
  explicit MeshCorners(const Mesh& mesh)
      : vertices_(mesh.vertices.data()),
        triangles_(mesh.triangles.data()),
        size_(mesh.triangle_count()) {}

  std::size_t size() const { return size_; }

  TriangleCorners operator[](std::size_t t) const {
    const Triangle& c = triangles_[t];
    return {vertices_[c[0]], vertices_[c[1]], vertices_[c[2]]};
  }

  // Asks for triangle t's vertex indices ahead of a read of its corners.
  void prefetch(std::size_t t) const { __builtin_prefetch(&triangles_[t]); }

 private:
  const Vec3* vertices_;
  const Triangle* triangles_;
  std::size_t size_;
};

}  // namespace ncv
