// The bridge between OpenMesh's TriMesh and the plain arrays: order kept both ways, every
// triangle kept where the halfedge structure refuses one, and a TriMesh checked as a file is.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "mesh/tri_mesh.hpp"
#include "nominal_fixtures.hpp"
#include "util/error.hpp"

namespace {

namespace fx = ncv::fixtures;
using ncv::TriMesh;

TriMesh triangle_fan() {
  TriMesh mesh;
  const auto a = mesh.add_vertex({0, 0, 0});
  const auto b = mesh.add_vertex({1, 0, 0});
  const auto c = mesh.add_vertex({0, 1, 0});
  const auto d = mesh.add_vertex({-1, 0, 0});
  mesh.add_face(b, c, a);  // corners not starting at the lowest index
  mesh.add_face(a, c, d);
  return mesh;
}

}  // namespace

TEST_CASE("a TriMesh's arrays keep its vertex order and each face's corner order", "[tri_mesh]") {
  const ncv::Mesh arrays = ncv::mesh_arrays(triangle_fan(), "fan");
  REQUIRE(arrays.vertex_count() == 4);
  CHECK(arrays.vertices[3] == ncv::Vec3(-1, 0, 0));
  REQUIRE(arrays.triangle_count() == 2);
  CHECK(arrays.triangles[0] == ncv::Triangle{1, 2, 0});
  CHECK(arrays.triangles[1] == ncv::Triangle{0, 2, 3});
}

TEST_CASE("arrays to TriMesh and back are the same arrays", "[tri_mesh]") {
  for (const ncv::Mesh& mesh :
       {fx::box({0, 0, 0}, {1, 2, 3}), fx::pocketed_block().mesh(0.5), fx::torus(3, 1, 24, 12)}) {
    std::vector<std::uint32_t> copied_from;
    const TriMesh tri = ncv::tri_mesh(mesh, &copied_from);
    CHECK(tri.n_vertices() == mesh.vertex_count());
    CHECK(copied_from.size() == mesh.vertex_count());
    const ncv::Mesh back = ncv::mesh_arrays(tri, "round trip");
    CHECK(back.vertices == mesh.vertices);
    CHECK(back.triangles == mesh.triangles);
    CHECK(ncv::mesh_hash(back) == ncv::mesh_hash(mesh));
  }
}

TEST_CASE("triangles the halfedge structure refuses get their own corners", "[tri_mesh]") {
  ncv::Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  // Three faces on the edge 0-1 (the third is refused), then a repeated corner.
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {2, 2, 4}};
  std::vector<std::uint32_t> copied_from;
  const TriMesh tri = ncv::tri_mesh(mesh, &copied_from);
  REQUIRE(tri.n_faces() == 4);
  REQUIRE(tri.n_vertices() == 5 + 6);
  REQUIRE(copied_from.size() == tri.n_vertices());
  const std::vector<std::uint32_t> copies(copied_from.begin() + 5, copied_from.end());
  CHECK(copies == std::vector<std::uint32_t>{0, 1, 4, 2, 2, 4});
  for (std::size_t v = 0; v < tri.n_vertices(); ++v) {
    CHECK(tri.point(TriMesh::VertexHandle(static_cast<int>(v))) == mesh.vertices[copied_from[v]]);
  }
  // Each face's corners stand for the triangle's corners, in order.
  const ncv::Mesh back = ncv::mesh_arrays(tri, "copies");
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) CHECK(copied_from[back.triangles[t][k]] == mesh.triangles[t][k]);
  }
}

TEST_CASE("a TriMesh is checked as a mesh file is", "[tri_mesh]") {
  CHECK_THROWS_WITH(ncv::mesh_arrays(TriMesh{}, "empty"), "empty: the mesh has no triangles");

  TriMesh with_nan = triangle_fan();
  with_nan.set_point(TriMesh::VertexHandle(1), {std::numeric_limits<double>::quiet_NaN(), 0, 0});
  CHECK_THROWS_WITH(ncv::mesh_arrays(with_nan, "nan"),
                    "nan: a vertex has a NaN or infinite coordinate");

  TriMesh far = triangle_fan();
  far.set_point(TriMesh::VertexHandle(2), {0, 1e101, 0});
  CHECK_THROWS_AS(ncv::mesh_arrays(far, "far"), ncv::InputError);

  TriMesh deleted = triangle_fan();
  deleted.request_face_status();
  deleted.request_edge_status();
  deleted.request_vertex_status();
  deleted.delete_face(TriMesh::FaceHandle(0));
  CHECK_THROWS_WITH(ncv::mesh_arrays(deleted, "edited"),
                    Catch::Contains("edited: ") && Catch::Contains("garbage_collection()"));
  deleted.garbage_collection();
  CHECK(ncv::mesh_arrays(deleted, "collected").triangle_count() == 1);
}
