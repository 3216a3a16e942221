// The boundary loops of an open surface on OpenMesh's halfedges: how many, each one's
// edges, length and where.
#include <catch2/catch.hpp>

#include "mesh/boundary_loops.hpp"
#include "mesh/halfedge_mesh.hpp"
#include "nominal_fixtures.hpp"

namespace {

namespace fx = ncv::fixtures;
using ncv::Vec3;

std::vector<ncv::BoundaryLoop> loops_of(const ncv::Mesh& mesh) {
  return ncv::boundary_loops(ncv::halfedge_mesh(mesh, ncv::build_edge_incidence(mesh)));
}

// The box [0, 1] x [0, 2] x [0, 3] with the triangles of its faces z = 3 (2, 3) and x = 1
// (10, 11) removed as asked.
ncv::Mesh box_without(std::vector<std::size_t> removed) {
  ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 2, 3});
  std::sort(removed.rbegin(), removed.rend());
  for (std::size_t t : removed) mesh.triangles.erase(mesh.triangles.begin() + std::ptrdiff_t(t));
  return mesh;
}

}  // namespace

TEST_CASE("boundary loops: none on a closed surface", "[boundary-loops]") {
  CHECK(loops_of(fx::box({0, 0, 0}, {1, 1, 1})).empty());
  CHECK(loops_of(fx::torus(4, 1, 16, 8)).empty());
}

TEST_CASE("boundary loops: a square hole is one loop of four edges", "[boundary-loops]") {
  const auto loops = loops_of(box_without({2, 3}));
  REQUIRE(loops.size() == 1);
  CHECK(loops[0].edges == 4);
  CHECK(loops[0].length == Approx(6.0));
  CHECK(loops[0].box.min == Vec3(0, 0, 3));
  CHECK(loops[0].box.max == Vec3(1, 2, 3));
  CHECK(loops[0].start[2] == 3);
}

TEST_CASE("boundary loops: two holes, two loops, adjacent holes merge", "[boundary-loops]") {
  const auto two = loops_of(box_without({2, 3, 8, 9}));  // top and x = 0 share an edge
  REQUIRE(two.size() == 1);
  CHECK(two[0].edges == 6);
  CHECK(two[0].length == Approx(2 * 1 + 2 * 3 + 2 * 2 - 2 * 2 + 2 * 2));
  const auto apart = loops_of(box_without({2, 3, 0, 1}));  // top and bottom: no shared edge
  REQUIRE(apart.size() == 2);
  for (const auto& loop : apart) {
    CHECK(loop.edges == 4);
    CHECK(loop.length == Approx(6.0));
  }
  CHECK(apart[0].box.min[2] != apart[1].box.min[2]);
}

TEST_CASE("boundary loops: translated into model coordinates", "[boundary-loops]") {
  const auto loops = ncv::translated(loops_of(box_without({2, 3})), Vec3(10, 20, 30));
  REQUIRE(loops.size() == 1);
  CHECK(loops[0].box.min == Vec3(10, 20, 33));
  CHECK(loops[0].box.max == Vec3(11, 22, 33));
  CHECK(loops[0].length == Approx(6.0));
}
