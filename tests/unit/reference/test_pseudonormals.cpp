// Pseudonormals on OpenMesh's halfedges and on the plain arrays: the same values to the bit,
// and a surface held on halfedges wherever OpenMesh can hold it.
#include <catch2/catch.hpp>

#include <tbb/global_control.h>

#include "mesh/halfedge_mesh.hpp"
#include "nominal_fixtures.hpp"
#include "reference/pseudonormals.hpp"
#include "reference/reference_surface.hpp"

namespace {

namespace fx = ncv::fixtures;

void check_bit_identical(const ncv::Mesh& mesh) {
  const ncv::EdgeIncidence incidence = ncv::build_edge_incidence(mesh);
  REQUIRE(ncv::holds_as_halfedge_mesh(mesh, ncv::analyse_topology(mesh, incidence)));
  const ncv::Pseudonormals arrays = ncv::array_pseudonormals(mesh, fx::corners_of(mesh), incidence);
  for (int threads : {1, 2}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const ncv::Pseudonormals halfedges =
        ncv::halfedge_pseudonormals(ncv::halfedge_mesh(mesh, incidence), incidence);
    CHECK(std::equal(halfedges.face.begin(), halfedges.face.end(), arrays.face.begin(),
                     arrays.face.end()));
    CHECK(halfedges.vertex == arrays.vertex);
    CHECK(halfedges.edge == arrays.edge);
    CHECK(halfedges.edge_of_slot == arrays.edge_of_slot);
  }
}

}  // namespace

TEST_CASE("pseudonormals: halfedges and arrays agree to the bit", "[pseudonormals]") {
  check_bit_identical(fx::box({0, 0, 0}, {1, 2, 3}));
  check_bit_identical(fx::torus(40, 10, 60, 30));
  check_bit_identical(fx::pocketed_block().mesh(0.7));
  ncv::Mesh open = fx::torus(40, 10, 60, 30);
  open.triangles.resize(open.triangles.size() - 7);
  open.vertices[3] = open.vertices[4];  // a degenerate face: no normal, no vote
  check_bit_identical(open);
}

TEST_CASE("reference surface: held on halfedges where OpenMesh can hold it", "[pseudonormals]") {
  const ncv::ReferenceSurface closed(fx::torus(40, 10, 60, 30), "torus");
  CHECK(closed.on_halfedges());
  CHECK(closed.boundary_loop_count() == 0);
  CHECK(closed.topology().closed());

  ncv::Mesh open_mesh = fx::box({0, 0, 0}, {1, 2, 3});
  open_mesh.triangles.erase(open_mesh.triangles.begin() + 2, open_mesh.triangles.begin() + 4);
  const ncv::ReferenceSurface open(open_mesh, "open");
  CHECK(open.on_halfedges());
  REQUIRE(open.boundary_loop_count() == 1);
  // In model coordinates, and the boundary edges counted on the halfedges are the arrays'.
  CHECK(open.boundary_loops()[0].box.min == ncv::Vec3(0, 0, 3));
  CHECK(open.boundary_loops()[0].box.max == ncv::Vec3(1, 2, 3));
  CHECK(open.topology() == ncv::analyse_topology(open_mesh, ncv::build_edge_incidence(open_mesh)));
  CHECK(open.automatic_sign_method() == ncv::SignMethod::winding);

  ncv::Mesh fin = fx::box({0, 0, 0}, {1, 1, 1});
  fin.vertices.push_back({0.5, -1, 0});
  fin.triangles.push_back({0, 1, 8});  // a third face on an edge
  const ncv::ReferenceSurface held_on_arrays(fin, "fin");
  CHECK_FALSE(held_on_arrays.on_halfedges());
  CHECK(held_on_arrays.boundary_loops().empty());
  CHECK(held_on_arrays.topology().non_manifold_edges == 1);
  CHECK(held_on_arrays.automatic_sign_method() == ncv::SignMethod::winding);
}

TEST_CASE("reference surface: an inward nominal is flipped before its halfedges are built",
          "[pseudonormals]") {
  const ncv::ReferenceSurface outward(fx::torus(40, 10, 60, 30), "torus");
  const ncv::ReferenceSurface inward(fx::flipped(fx::torus(40, 10, 60, 30)), "torus");
  REQUIRE(inward.flipped());
  REQUIRE(inward.on_halfedges());
  // Flipped back, it is the outward torus: every pseudonormal the same to the bit (its edges
  // are numbered on the mesh as given, so they are compared through the triangles).
  CHECK(inward.normals().vertex == outward.normals().vertex);
  for (std::size_t t = 0; t < inward.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      CHECK(inward.pseudonormal(t, ncv::edge_feature(k)) ==
            outward.pseudonormal(t, ncv::edge_feature(k)));
    }
  }
}
