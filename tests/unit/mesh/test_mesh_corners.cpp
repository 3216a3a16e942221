#include <catch2/catch.hpp>

#include "mesh/mesh_corners.hpp"
#include "nominal_fixtures.hpp"

namespace fx = ncv::fixtures;

TEST_CASE("a mesh's corners are its vertices in each triangle's index order", "[mesh]") {
  ncv::Mesh mesh = fx::torus(3, 1, 12, 8);
  // Reordered indices must be followed: corner k is always vertices[triangles[t][k]].
  std::swap(mesh.triangles[5][1], mesh.triangles[5][2]);
  const ncv::MeshCorners corners(mesh);
  REQUIRE(corners.size() == mesh.triangle_count());
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const ncv::TriangleCorners c = corners[t];
    for (int k = 0; k < 3; ++k) CHECK(c[k] == mesh.vertices[mesh.triangles[t][k]]);
  }
}
