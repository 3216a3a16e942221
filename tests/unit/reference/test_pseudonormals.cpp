// Pseudonormals on OpenMesh's halfedges, on the plain arrays and around the arrays' fans: the
// same values to the bit, and a surface held on halfedges wherever OpenMesh can hold it.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

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
  const ncv::Pseudonormals arrays = ncv::array_pseudonormals(mesh, incidence);
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

// Every vertex's and edge's pseudonormal found around its fan is the arrays' up-front one.
void check_fans_agree(const ncv::Mesh& mesh) {
  const ncv::EdgeIncidence incidence = ncv::build_edge_incidence(mesh);
  REQUIRE(ncv::fans_walkable(incidence, ncv::analyse_topology(mesh, incidence)));
  const ncv::MeshCorners corners(mesh);
  const ncv::Pseudonormals arrays = ncv::array_pseudonormals(mesh, incidence);
  const ncv::FanPseudonormals fans(incidence);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    CHECK(ncv::FanPseudonormals::face(corners, t) == arrays.face[t]);
    for (int k = 0; k < 3; ++k) {
      CHECK(fans.vertex(mesh, t, k) == arrays.vertex[mesh.triangles[t][k]]);
      const std::uint32_t e = arrays.edge_of_slot[3 * t + static_cast<std::size_t>(k)];
      CHECK(fans.edge(corners, t, k) == (e == ncv::kNoEdge ? ncv::Vec3(0, 0, 0) : arrays.edge[e]));
    }
  }
}

// Two apexes joined to a ring of n points: a vertex on n faces at each apex.
ncv::Mesh bipyramid(int n) {
  ncv::Mesh mesh;
  mesh.vertices = {{0, 0, 1}, {0, 0, -1}};
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    mesh.vertices.push_back({std::cos(a), std::sin(a), 0.1 * (i % 3)});
  }
  for (std::uint32_t i = 0; i < static_cast<std::uint32_t>(n); ++i) {
    const std::uint32_t a = 2 + i, b = 2 + (i + 1) % static_cast<std::uint32_t>(n);
    mesh.triangles.push_back({0, a, b});
    mesh.triangles.push_back({1, b, a});
  }
  return mesh;
}

}  // namespace

TEST_CASE("pseudonormals: around the fans as the arrays give them, to the bit", "[pseudonormals]") {
  check_fans_agree(fx::box({0, 0, 0}, {1, 2, 3}));
  check_fans_agree(fx::torus(40, 10, 60, 30));
  check_fans_agree(fx::flipped(fx::torus(40, 10, 60, 30)));
  check_fans_agree(fx::pocketed_block().mesh(0.7));
  check_fans_agree(bipyramid(7));
  check_fans_agree(bipyramid(41));  // more faces at a vertex than the walk keeps on the stack
  // Shuffled: the fan meets the faces out of order, the sums add them in order.
  ncv::Mesh shuffled = fx::torus(40, 10, 60, 30);
  std::mt19937_64 rng(7);
  std::shuffle(shuffled.triangles.begin(), shuffled.triangles.end(), rng);
  check_fans_agree(shuffled);
  ncv::Mesh degenerate = fx::torus(40, 10, 60, 30);
  degenerate.vertices[3] = degenerate.vertices[4];  // faces with no normal: no vote
  check_fans_agree(degenerate);
}

TEST_CASE("pseudonormals: fans walkable only on a closed surface with one fan a vertex",
          "[pseudonormals]") {
  const auto walkable = [](const ncv::Mesh& mesh) {
    const ncv::EdgeIncidence incidence = ncv::build_edge_incidence(mesh);
    return ncv::fans_walkable(incidence, ncv::analyse_topology(mesh, incidence));
  };
  CHECK(walkable(fx::box({0, 0, 0}, {1, 1, 1})));
  ncv::Mesh open = fx::box({0, 0, 0}, {1, 1, 1});
  open.triangles.pop_back();
  CHECK_FALSE(walkable(open));
  ncv::Mesh fin = fx::box({0, 0, 0}, {1, 1, 1});
  fin.vertices.push_back({0.5, -1, 0});
  fin.triangles.push_back({0, 1, 8});
  CHECK_FALSE(walkable(fin));
  // Two boxes sharing one corner: two fans at that vertex.
  ncv::Mesh pinched = fx::box({0, 0, 0}, {1, 1, 1});
  const ncv::Mesh other = fx::translated(fx::box({0, 0, 0}, {1, 1, 1}), {1, 1, 1});
  const auto base = static_cast<std::uint32_t>(pinched.vertices.size());
  const auto at = [&](ncv::Vec3 p) {
    return static_cast<std::uint32_t>(
        std::find(pinched.vertices.begin(), pinched.vertices.end(), p) - pinched.vertices.begin());
  };
  std::vector<std::uint32_t> index;
  for (const ncv::Vec3& p : other.vertices) {
    const std::uint32_t shared = at(p);
    index.push_back(shared < base ? shared : static_cast<std::uint32_t>(pinched.vertices.size()));
    if (shared >= base) pinched.vertices.push_back(p);
  }
  for (const ncv::Triangle& t : other.triangles) {
    pinched.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  }
  REQUIRE(pinched.vertex_count() == 15);
  CHECK_FALSE(walkable(pinched));
  ncv::Mesh repeated = fx::box({0, 0, 0}, {1, 1, 1});
  repeated.triangles.push_back({0, 0, 1});
  CHECK_FALSE(walkable(repeated));
}

TEST_CASE("reference surface: on the arrays the pseudonormals are the halfedges'",
          "[pseudonormals]") {
  for (const ncv::Mesh& mesh :
       {fx::torus(40, 10, 60, 30), fx::flipped(fx::pocketed_block().mesh(0.7))}) {
    const ncv::ReferenceSurface halfedges(mesh, "part");
    const ncv::ReferenceSurface arrays(mesh, "part", ncv::SurfaceHolding::arrays);
    REQUIRE(halfedges.on_halfedges());
    REQUIRE_FALSE(arrays.on_halfedges());
    CHECK(arrays.normals().vertex.empty());  // each worked out (around its fan) when asked
    CHECK(arrays.normals().face.empty());
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      CHECK(arrays.face_normal(t) == halfedges.face_normal(t));
      for (int f = 0; f < 7; ++f) {
        const auto feature = static_cast<ncv::TriangleFeature>(f);
        CHECK(arrays.pseudonormal(t, feature) == halfedges.pseudonormal(t, feature));
      }
    }
  }
}

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
