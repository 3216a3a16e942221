// Topology of nominal meshes: closed, manifold, consistently oriented, outward, and the
// counts that explain why not.
#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include <tbb/global_control.h>

#include "mesh/mesh_topology.hpp"
#include "nominal_fixtures.hpp"

namespace {

namespace fx = ncv::fixtures;

ncv::TopologyReport analyse(const ncv::Mesh& mesh) {
  return ncv::analyse_topology(mesh, ncv::build_edge_incidence(mesh));
}

}  // namespace

TEST_CASE("topology of a closed outward box", "[topology]") {
  const ncv::TopologyReport r = analyse(fx::box({0, 0, 0}, {1, 2, 3}));
  CHECK(r.triangles == 12);
  CHECK(r.edges == 18);
  CHECK(r.closed());
  CHECK(r.manifold());
  CHECK(r.consistently_oriented());
  CHECK(r.outward());
  CHECK(r.signed_volume == Approx(6.0));
  CHECK(r.boundary_edges == 0);
  CHECK(r.degenerate_triangles == 0);
  CHECK(r.duplicate_triangles == 0);
}

TEST_CASE("topology of lattice solids and a torus", "[topology]") {
  const ncv::TopologyReport block = analyse(fx::pocketed_block().mesh(0.5));
  CHECK(block.closed());
  CHECK(block.manifold());
  CHECK(block.consistently_oriented());
  CHECK(block.signed_volume == Approx((32 - 4) * 0.125));
  const ncv::TopologyReport ring = analyse(fx::torus(3, 1, 48, 24));
  CHECK(ring.closed());
  CHECK(ring.manifold());
  CHECK(ring.consistently_oriented());
  CHECK(ring.outward());
  CHECK(ring.edges == 3 * 48 * 24);
}

TEST_CASE("topology: an open box has boundary edges", "[topology]") {
  ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 1, 1});
  mesh.triangles.erase(mesh.triangles.begin() + 2, mesh.triangles.begin() + 4);  // the top
  const ncv::TopologyReport r = analyse(mesh);
  CHECK_FALSE(r.closed());
  CHECK(r.boundary_edges == 4);
  CHECK(r.manifold());
  CHECK(r.consistently_oriented());
  CHECK(r.edges == 17);
}

TEST_CASE("topology: orientation", "[topology]") {
  SECTION("all triangles flipped: consistent but inward") {
    const ncv::TopologyReport r = analyse(fx::flipped(fx::box({0, 0, 0}, {1, 1, 1})));
    CHECK(r.closed());
    CHECK(r.consistently_oriented());
    CHECK_FALSE(r.outward());
    CHECK(r.signed_volume == Approx(-1.0));
  }
  SECTION("one triangle flipped: its three edges are misoriented") {
    ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 1, 1});
    std::swap(mesh.triangles[5][1], mesh.triangles[5][2]);
    const ncv::TopologyReport r = analyse(mesh);
    CHECK(r.closed());
    CHECK(r.misoriented_edges == 3);
    CHECK_FALSE(r.consistently_oriented());
  }
}

TEST_CASE("topology: non-manifold edges and vertices", "[topology]") {
  SECTION("three triangles on one edge") {
    ncv::Mesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const ncv::TopologyReport r = analyse(mesh);
    CHECK(r.non_manifold_edges == 1);
    CHECK_FALSE(r.manifold());
    CHECK_FALSE(r.closed());
    CHECK(r.boundary_edges == 6);
  }
  SECTION("two boxes touching at one corner") {
    ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 1, 1});
    const ncv::Mesh other = fx::box({1, 1, 1}, {2, 2, 2});
    // Weld the shared corner (1,1,1): vertex 7 of the first, vertex 0 of the second.
    std::vector<std::uint32_t> map(8);
    for (std::uint32_t v = 0; v < 8; ++v) {
      if (v == 0) {
        map[v] = 7;
      } else {
        map[v] = static_cast<std::uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(other.vertices[v]);
      }
    }
    for (const ncv::Triangle& t : other.triangles)
      mesh.triangles.push_back({map[t[0]], map[t[1]], map[t[2]]});
    const ncv::TopologyReport r = analyse(mesh);
    CHECK(r.closed());
    CHECK(r.consistently_oriented());
    CHECK(r.non_manifold_edges == 0);
    CHECK(r.non_manifold_vertices == 1);
    CHECK_FALSE(r.manifold());
  }
}

TEST_CASE("non-manifold vertices counted alike on any thread count", "[topology]") {
  // 3000 unit boxes along the diagonal, each touching the next at one welded corner: 2999
  // vertices where two fans meet; a third box at every tenth joint makes three fans there.
  ncv::Mesh mesh;
  std::uint32_t previous_top = 0;
  const auto add_box = [&](ncv::Vec3 low, std::optional<std::uint32_t> weld_low) {
    const ncv::Mesh box = fx::box(low, low + ncv::Vec3(1, 1, 1));
    std::vector<std::uint32_t> map(box.vertices.size());
    for (std::uint32_t v = 0; v < box.vertices.size(); ++v) {
      if (v == 0 && weld_low) {
        map[v] = *weld_low;
      } else {
        map[v] = static_cast<std::uint32_t>(mesh.vertices.size());
        mesh.vertices.push_back(box.vertices[v]);
      }
    }
    for (const ncv::Triangle& t : box.triangles) {
      mesh.triangles.push_back({map[t[0]], map[t[1]], map[t[2]]});
    }
    return map[7];  // the corner (1,1,1) above low
  };
  std::uint64_t triple = 0;
  for (int k = 0; k < 3000; ++k) {
    const ncv::Vec3 low(k, k, k);
    const std::uint32_t joint = previous_top;
    previous_top = add_box(low, k > 0 ? std::optional<std::uint32_t>(joint) : std::nullopt);
    if (k > 0 && k % 10 == 0) {
      // A box below-right of the joint, touching it with its own corner (1,1,1): here its
      // corner 7 is welded to the joint instead of corner 0, by moving it so.
      const ncv::Mesh box = fx::box(low - ncv::Vec3(1, 1, 1), low);
      std::vector<std::uint32_t> map(box.vertices.size());
      for (std::uint32_t v = 0; v < box.vertices.size(); ++v) {
        map[v] = v == 7 ? joint : static_cast<std::uint32_t>(mesh.vertices.size());
        if (v != 7) mesh.vertices.push_back(box.vertices[v] + ncv::Vec3(0.5, -3, 0));
      }
      for (const ncv::Triangle& t : box.triangles) {
        mesh.triangles.push_back({map[t[0]], map[t[1]], map[t[2]]});
      }
      ++triple;
    }
  }
  for (const int threads : {1, 2, 3}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    INFO(threads << " threads, " << triple << " joints of three fans");
    const ncv::TopologyReport r = analyse(mesh);
    CHECK(r.closed());
    CHECK(r.non_manifold_edges == 0);
    CHECK(r.non_manifold_vertices == 2999);
  }
}

TEST_CASE("topology: degenerate and duplicate triangles", "[topology]") {
  ncv::Mesh mesh = fx::box({0, 0, 0}, {1, 1, 1});
  SECTION("a repeated corner takes no part in the edges") {
    mesh.triangles.push_back({0, 0, 1});
    const ncv::TopologyReport r = analyse(mesh);
    CHECK(r.degenerate_triangles == 1);
    CHECK(r.closed());  // the edge {0, 1} is not counted three times
    CHECK(r.edges == 18);
  }
  SECTION("a zero-area triangle filling a T-junction keeps the mesh closed") {
    // Split the front (y = 0) face's edge 0-1 at its midpoint m: its two triangles become
    // three, and the degenerate triangle (0, 1, m) closes the crack against the bottom face.
    ncv::Mesh cracked = mesh;
    const auto m = static_cast<std::uint32_t>(cracked.vertices.size());
    cracked.vertices.push_back({0.5, 0, 0});
    // Front face triangles are {0,1,4} and {1,5,4}; the bottom face uses 0-1 too.
    cracked.triangles[4] = {0, m, 4};
    cracked.triangles.push_back({m, 1, 4});
    cracked.triangles.push_back({0, 1, m});
    const ncv::TopologyReport r = analyse(cracked);
    CHECK(r.degenerate_triangles == 1);
    CHECK(r.closed());
    CHECK(r.consistently_oriented());
  }
  SECTION("a duplicated triangle, in any corner order") {
    mesh.triangles.push_back({mesh.triangles[0][1], mesh.triangles[0][2], mesh.triangles[0][0]});
    mesh.triangles.push_back({mesh.triangles[3][0], mesh.triangles[3][2], mesh.triangles[3][1]});
    const ncv::TopologyReport r = analyse(mesh);
    CHECK(r.duplicate_triangles == 2);
    CHECK(r.non_manifold_edges == 6);
    CHECK_FALSE(r.closed());
  }
}

TEST_CASE("edge incidence groups the slots of each edge", "[topology]") {
  ncv::Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {2, 1, 3}};
  const ncv::EdgeIncidence incidence = ncv::build_edge_incidence(mesh);
  CHECK(incidence.edge_count() == 5);
  // Slot 1 (1 -> 2) and slot 3 (2 -> 1) share the diagonal.
  CHECK(incidence.edge_of_slot[1] == incidence.edge_of_slot[3]);
  const std::uint32_t diagonal = incidence.edge_of_slot[1];
  CHECK(incidence.slot_count(diagonal) == 2);
  CHECK(incidence.slots[incidence.edge_begin[diagonal]] == 1);
  CHECK(incidence.slots[incidence.edge_begin[diagonal] + 1] == 3);
  for (std::uint32_t s : {0u, 2u, 4u, 5u})
    CHECK(incidence.slot_count(incidence.edge_of_slot[s]) == 1);
}

namespace {

// A torus of 65 k triangles (several parallel chunks of vertices, edges and triangles) with
// every kind of defect: duplicated, flipped and missing triangles, a repeated corner.
ncv::Mesh defective_torus() {
  ncv::Mesh mesh = fx::torus(3, 1, 256, 128);
  for (std::size_t t = 0; t < mesh.triangles.size(); t += 997) {
    mesh.triangles.push_back(mesh.triangles[t]);  // duplicated
  }
  for (std::size_t t = 500; t < 60000; t += 4001) {
    std::swap(mesh.triangles[t][1], mesh.triangles[t][2]);  // flipped
  }
  for (std::size_t t = 1000; t < 60000; t += 5003) {
    mesh.triangles[t] = mesh.triangles[t + 1];  // missing: its edges become boundary
  }
  mesh.triangles.push_back({7, 7, 8});  // repeated corner
  return mesh;
}

}  // namespace

TEST_CASE("edge incidence: edges numbered by (lower, higher) vertex, on any thread count",
          "[topology]") {
  const ncv::Mesh mesh = defective_torus();
  const auto build = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return std::pair{ncv::build_edge_incidence(mesh), analyse(mesh)};
  };
  const auto [one, one_report] = build(1);
  const auto [two, two_report] = build(2);
  CHECK(one.edge_of_slot == two.edge_of_slot);
  CHECK(one.edge_begin == two.edge_begin);
  CHECK(one.slots == two.slots);
  CHECK(one_report == two_report);
  CHECK(two_report.degenerate_triangles == 1);
  CHECK(two_report.duplicate_triangles >= 66);  // 66 copies, plus the missing triangles' twins
  CHECK(two_report.boundary_edges > 0);
  CHECK(two_report.misoriented_edges > 0);

  // Each edge's slots join the same two vertices; edges ascend by (lower, higher) vertex;
  // each slot's edge lists it; the repeated-corner triangle's slots have none.
  const auto ends = [&](std::uint32_t slot) {
    const ncv::Triangle& t = mesh.triangles[slot / 3];
    const std::uint32_t a = t[slot % 3], b = t[(slot % 3 + 1) % 3];
    return std::pair{std::min(a, b), std::max(a, b)};
  };
  std::size_t faults = 0;
  for (std::size_t e = 0; e < two.edge_count(); ++e) {
    const auto first = ends(two.slots[two.edge_begin[e]]);
    if (e > 0) faults += !(ends(two.slots[two.edge_begin[e - 1]]) < first);
    for (std::uint32_t i = two.edge_begin[e]; i < two.edge_begin[e + 1]; ++i) {
      faults += ends(two.slots[i]) != first;
      faults += two.edge_of_slot[two.slots[i]] != e;
    }
  }
  CHECK(faults == 0);
  const std::size_t last = mesh.triangles.size() - 1;
  for (std::size_t k = 0; k < 3; ++k) CHECK(two.edge_of_slot[3 * last + k] == ncv::kNoEdge);
  CHECK(two.edge_begin.back() == two.slots.size());
}

TEST_CASE("duplicate triangles counted as sorting every triangle would", "[topology]") {
  ncv::Mesh mesh = defective_torus();
  // Three copies of one triangle in other corner orders, and repeated-corner triangles twice.
  const ncv::Triangle t = mesh.triangles[12345];
  mesh.triangles.push_back({t[2], t[0], t[1]});
  mesh.triangles.push_back({t[1], t[0], t[2]});
  mesh.triangles.push_back({8, 7, 7});
  mesh.triangles.push_back({9, 9, 9});
  mesh.triangles.push_back({9, 9, 9});
  // Many triangles on one edge (a fan), two of them the same.
  for (std::uint32_t v = 100; v < 140; ++v) mesh.triangles.push_back({0, 1, v});
  mesh.triangles.push_back({1, 120, 0});
  std::vector<ncv::Triangle> sorted = mesh.triangles;
  for (ncv::Triangle& s : sorted) std::sort(s.begin(), s.end());
  std::sort(sorted.begin(), sorted.end());
  std::uint64_t expected = 0;
  for (std::size_t i = 1; i < sorted.size(); ++i) expected += sorted[i] == sorted[i - 1];
  CHECK(expected > 70);
  CHECK(analyse(mesh).duplicate_triangles == expected);
}

TEST_CASE("degenerate triangle predicate", "[topology]") {
  const ncv::Vec3 a{0, 0, 0}, b{1, 0, 0};
  CHECK_FALSE(ncv::is_degenerate_triangle(a, b, {0, 1, 0}));
  CHECK_FALSE(ncv::is_degenerate_triangle(a, b, {0.5, 1e-8, 0}));
  CHECK(ncv::is_degenerate_triangle(a, b, {0.5, 1e-11, 0}));
  CHECK(ncv::is_degenerate_triangle(a, b, {2, 0, 0}));
  CHECK(ncv::is_degenerate_triangle(a, a, a));
}
