// OpenMesh's halfedge structure built from the edge incidence in parallel: the same
// connectivity add_face builds, accepted by OpenMesh's own checker, and refused to meshes
// OpenMesh cannot hold as they are.
#include <catch2/catch.hpp>

#include <OpenMesh/Tools/Utils/MeshCheckerT.hh>
#include <algorithm>
#include <sstream>

#include "mesh/halfedge_mesh.hpp"
#include "nominal_fixtures.hpp"

namespace {

namespace fx = ncv::fixtures;
using ncv::TriMesh;

// The box without its top (triangles 2 and 3: z = hi): one square hole.
ncv::Mesh open_box() {
  ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 2, 3});
  mesh.triangles.erase(mesh.triangles.begin() + 2, mesh.triangles.begin() + 4);
  return mesh;
}

TriMesh built(const ncv::Mesh& mesh) {
  const ncv::EdgeIncidence incidence = ncv::build_edge_incidence(mesh);
  REQUIRE(ncv::holds_as_halfedge_mesh(mesh, ncv::analyse_topology(mesh, incidence)));
  return ncv::halfedge_mesh(mesh, incidence);
}

// What add_face makes of the same arrays, compared element by element in a way that does
// not depend on how either numbers its edges.
void check_same_as_add_face(const ncv::Mesh& mesh) {
  const TriMesh ours = built(mesh);
  std::vector<std::uint32_t> copied_from;
  const TriMesh reference = ncv::tri_mesh(mesh, &copied_from);
  REQUIRE(reference.n_vertices() == mesh.vertex_count());  // every face accepted
  std::ostringstream problems;
  CHECK(OpenMesh::Utils::MeshCheckerT<TriMesh>(ours).check(
      OpenMesh::Utils::MeshCheckerT<TriMesh>::CHECK_ALL, problems));
  CHECK(problems.str().empty());
  CHECK(ours.n_edges() == reference.n_edges());
  CHECK(ours.n_faces() == reference.n_faces());
  for (const auto f : ours.faces()) {
    std::vector<int> a, b;
    for (const auto v : f.vertices()) a.push_back(v.idx());
    for (const auto v : reference.fv_range(reference.face_handle(static_cast<unsigned>(f.idx()))))
      b.push_back(v.idx());
    // The same cycle of corners (add_face may start it at another corner).
    std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
    std::rotate(b.begin(), std::min_element(b.begin(), b.end()), b.end());
    CHECK(a == b);
  }
  for (const auto v : ours.vertices()) {
    const auto other = reference.vertex_handle(static_cast<unsigned>(v.idx()));
    CHECK(ours.valence(v) == reference.valence(other));
    CHECK(ours.is_boundary(v) == reference.is_boundary(other));
    std::vector<int> a, b;
    for (const auto f : v.faces()) a.push_back(f.idx());
    for (const auto f : reference.vf_range(other)) b.push_back(f.idx());
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    CHECK(a == b);
  }
  std::size_t boundary = 0, reference_boundary = 0;
  for (const auto h : ours.halfedges()) boundary += ours.is_boundary(h);
  for (const auto h : reference.halfedges()) reference_boundary += reference.is_boundary(h);
  CHECK(boundary == reference_boundary);
}

}  // namespace

TEST_CASE("halfedge mesh: the connectivity add_face builds", "[halfedge]") {
  check_same_as_add_face(fx::box({0, 0, 0}, {1, 1, 1}));
  check_same_as_add_face(fx::torus(4, 1, 24, 12));
  check_same_as_add_face(fx::pocketed_block().mesh(1.0));
  check_same_as_add_face(open_box());
  ncv::Mesh strip = fx::torus(4, 1, 24, 12);
  strip.triangles.resize(strip.triangles.size() / 2);  // half a torus: two open rings
  check_same_as_add_face(strip);
}

TEST_CASE("halfedge mesh: a face runs from corner 0, an edge's halfedge 0 along its lower slot",
          "[halfedge]") {
  const ncv::Mesh mesh = open_box();
  const ncv::EdgeIncidence incidence = ncv::build_edge_incidence(mesh);
  const TriMesh halfedges = ncv::halfedge_mesh(mesh, incidence);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const auto h = halfedges.halfedge_handle(TriMesh::FaceHandle(static_cast<int>(t)));
    CHECK(halfedges.from_vertex_handle(h).idx() == static_cast<int>(mesh.triangles[t][0]));
    for (std::uint32_t k = 0; k < 3; ++k) {
      const auto slot = static_cast<std::uint32_t>(3 * t + k);
      const auto hk = ncv::slot_halfedge(incidence, slot);
      CHECK(halfedges.edge_handle(hk).idx() == static_cast<int>(incidence.edge_of_slot[slot]));
      CHECK(halfedges.face_handle(hk).idx() == static_cast<int>(t));
    }
  }
}

TEST_CASE("halfedge mesh: what OpenMesh cannot hold as it is", "[halfedge]") {
  const auto holds = [](const ncv::Mesh& mesh) {
    return ncv::holds_as_halfedge_mesh(
        mesh, ncv::analyse_topology(mesh, ncv::build_edge_incidence(mesh)));
  };
  ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 1, 1});
  CHECK(holds(mesh));
  mesh.vertices.push_back({0.5, -1, 0});
  mesh.triangles.push_back({0, 1, 8});  // a third face on edge {0, 1}
  CHECK_FALSE(holds(mesh));
  mesh = fx::box({0, 0, 0}, {1, 1, 1});
  std::swap(mesh.triangles[0][1], mesh.triangles[0][2]);  // a flipped neighbour
  CHECK_FALSE(holds(mesh));
  mesh = fx::box({0, 0, 0}, {1, 1, 1});
  mesh.triangles.push_back({0, 0, 1});  // a repeated corner
  CHECK_FALSE(holds(mesh));
  mesh = fx::box({0, 0, 0}, {1, 1, 1});
  const ncv::Mesh other = fx::box({1, 1, 1}, {2, 2, 2});  // touching at vertex 7 only
  for (const ncv::Triangle& t : other.triangles) {
    ncv::Triangle moved;
    for (int k = 0; k < 3; ++k) moved[k] = t[k] == 0 ? 7u : t[k] + 8u;
    mesh.triangles.push_back(moved);
  }
  mesh.vertices.insert(mesh.vertices.end(), other.vertices.begin(), other.vertices.end());
  CHECK_FALSE(holds(mesh));  // two fans at one vertex
}
