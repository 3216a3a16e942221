// A mesh whose facets come in random order gets its vertices renumbered in a spatial order
// when read; the triangles, their order and orientation, and so every position, stay.
#include <catch2/catch.hpp>

#include <tbb/global_control.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "mesh/mesh_reader.hpp"
#include "mesh/vertex_order.hpp"
#include "nominal_fixtures.hpp"

namespace {

namespace fx = ncv::fixtures;
using fx::shuffled_facets;

}  // namespace

TEST_CASE("only a large mesh numbered out of spatial order counts as scattered", "[mesh]") {
  const ncv::Mesh torus = fx::torus(40, 10, 400, 200);  // 80,000 vertices
  REQUIRE(torus.vertex_count() >= ncv::kLeastVerticesToOrder);
  CHECK_FALSE(ncv::vertices_scattered(torus));
  CHECK(ncv::vertices_scattered(shuffled_facets(torus, 1)));
  CHECK_FALSE(ncv::vertices_scattered(shuffled_facets(fx::torus(40, 10, 60, 30), 1)));  // small
}

TEST_CASE("spatial order renames the vertices and keeps every triangle's corners", "[mesh]") {
  const ncv::Mesh before = shuffled_facets(fx::torus(40, 10, 400, 200), 7);
  ncv::Mesh after = before;
  ncv::order_vertices_spatially(after);
  REQUIRE(after.vertex_count() == before.vertex_count());
  REQUIRE(after.triangle_count() == before.triangle_count());
  bool same = true;
  for (std::size_t t = 0; t < before.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) same = same && after.corner(t, k) == before.corner(t, k);
  }
  CHECK(same);
  std::vector<std::uint32_t> used(after.vertex_count(), 0);  // a permutation: each once
  for (const ncv::Triangle& t : after.triangles) {
    for (const std::uint32_t v : t) used[v] = 1;
  }
  CHECK(std::count(used.begin(), used.end(), 1u) == static_cast<long>(after.vertex_count()));
  CHECK_FALSE(ncv::vertices_scattered(after));
  // The same numbering whatever the threads.
  for (const int threads : {1, 2, 3}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    ncv::Mesh again = before;
    ncv::order_vertices_spatially(again);
    CHECK(again.triangles == after.triangles);
    CHECK(again.vertices == after.vertices);
  }
}

TEST_CASE("reading a binary STL of shuffled facets numbers its vertices in spatial order",
          "[mesh]") {
  const ncv::Mesh mesh = shuffled_facets(fx::torus(40, 10, 400, 200), 3);
  std::vector<char> bytes(84 + 50 * mesh.triangle_count(), 0);
  const auto count = static_cast<std::uint32_t>(mesh.triangle_count());
  std::memcpy(bytes.data() + 80, &count, 4);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      for (int axis = 0; axis < 3; ++axis) {
        const auto x = static_cast<float>(mesh.corner(t, k)[axis]);
        std::memcpy(bytes.data() + 84 + 50 * t + 12 + 12 * k + 4 * axis, &x, 4);
      }
    }
  }
  const ncv::Mesh read = ncv::parse_mesh(bytes, "part.stl");
  REQUIRE(read.triangle_count() == mesh.triangle_count());
  CHECK_FALSE(ncv::vertices_scattered(read));
  bool same = true;  // the file's triangles, in its order, at its (float) corners
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    for (int k = 0; k < 3; ++k) {
      for (int axis = 0; axis < 3; ++axis) {
        same = same && read.corner(t, k)[axis] ==
                           static_cast<double>(static_cast<float>(mesh.corner(t, k)[axis]));
      }
    }
  }
  CHECK(same);
}
