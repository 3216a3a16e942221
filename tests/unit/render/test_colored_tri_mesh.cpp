// The coloured TriMesh: the PLY's colours and the signed error, by name, at every vertex,
// copies of refused triangles' corners included.
#include <catch2/catch.hpp>

#include <OpenMesh/Core/Utils/PropertyManager.hh>
#include <cmath>
#include <limits>

#include "render/colored_tri_mesh.hpp"

TEST_CASE("the coloured TriMesh carries the map's colours and the errors by name",
          "[colored_tri_mesh]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ncv::ErrorMesh error_mesh;
  error_mesh.mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  error_mesh.mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // the third is refused
  error_mesh.values = {-0.3, 0.0, 0.05, 0.4, nan};
  const ncv::ColorMap map =
      ncv::make_color_map(ncv::ColorMapKind::tolerance, {-0.5, 0.5}, ncv::Tolerance{-0.1, 0.1});

  ncv::TriMesh mesh = ncv::colored_tri_mesh(error_mesh, map);
  REQUIRE(mesh.n_faces() == 3);
  REQUIRE(mesh.n_vertices() == 5 + 3);
  REQUIRE(mesh.has_vertex_colors());
  const auto error = OpenMesh::VProp<double>(mesh, ncv::kSignedErrorProperty);
  const std::vector<std::size_t> stands_for = {0, 1, 2, 3, 4, 0, 1, 4};
  for (const auto vertex : mesh.vertices()) {
    const double value = error_mesh.values[stands_for[vertex.idx()]];
    const ncv::Rgb rgb = map.rgb(value);
    CHECK(mesh.color(vertex) == ncv::TriMesh::Color(rgb[0], rgb[1], rgb[2]));
    if (std::isnan(value)) {
      CHECK(std::isnan(error[vertex]));
    } else {
      CHECK(error[vertex] == value);
    }
  }
  CHECK(mesh.color(ncv::TriMesh::VertexHandle(4)) ==
        ncv::TriMesh::Color(ncv::kNoValueColor[0], ncv::kNoValueColor[1], ncv::kNoValueColor[2]));
}
