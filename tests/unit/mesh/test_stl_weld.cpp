// Binary STL welding by partitions (mesh/facet_weld.hpp): the same mesh, vertex numbers and
// coordinates included, as one VertexWelder over every corner in file order, on files whose
// corners repeat near and far (across the blocks the corners are counted in), in file order
// or shuffled, with -0 and +0, on any thread count; and a non-finite coordinate named at its
// first facet wherever it lies.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <tbb/global_control.h>

#include "mesh/mesh_reader.hpp"
#include "mesh/vertex_welder.hpp"
#include "util/error.hpp"

using namespace ncv;

namespace {

std::uint64_t next_bits(std::uint64_t& state) {  // splitmix64
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// `facets` facets whose corners come from a pool of `points` points (some with -0 or +0
// coordinates), each corner drawn near the facet's place in the file or anywhere, so that
// points recur within a block, in the next one and far away.
std::vector<float> random_corners(std::uint64_t seed, std::size_t facets, std::size_t points) {
  std::uint64_t state = seed;
  std::vector<float> pool(3 * points);
  for (float& c : pool) {
    const std::uint64_t r = next_bits(state) % 16;
    c = r == 0 ? 0.0f : r == 1 ? -0.0f : static_cast<float>(next_bits(state) % 1000) * 0.25f;
  }
  std::vector<float> corners(9 * facets);
  for (std::size_t f = 0; f < facets; ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::size_t near = f * points / facets + next_bits(state) % 64;
      const std::size_t p = next_bits(state) % 4 == 0 ? next_bits(state) % points : near % points;
      std::memcpy(&corners[9 * f + 3 * k], &pool[3 * p], 3 * sizeof(float));
    }
  }
  return corners;
}

std::vector<char> binary_stl(const std::vector<float>& corners) {
  const auto count = static_cast<std::uint32_t>(corners.size() / 9);
  std::vector<char> bytes(84 + 50 * std::size_t{count}, 0);
  std::memcpy(bytes.data() + 80, &count, 4);
  for (std::size_t f = 0; f < count; ++f) {
    std::memcpy(bytes.data() + 84 + 50 * f + 12, &corners[9 * f], 9 * sizeof(float));
  }
  return bytes;
}

// One VertexWelder over every corner in file order.
Mesh welded_in_order(const std::vector<float>& corners) {
  VertexWelder welder(corners.size() / 18 + 16);
  Mesh mesh;
  for (std::size_t f = 0; 9 * f < corners.size(); ++f) {
    Triangle t;
    for (int k = 0; k < 3; ++k) {
      const float* p = &corners[9 * f + 3 * k];
      t[k] = welder.weld(Vec3(p[0], p[1], p[2]));
    }
    mesh.triangles.push_back(t);
  }
  mesh.vertices = welder.take_vertices();
  return mesh;
}

void check_same(const Mesh& a, const Mesh& b) {
  REQUIRE(a.triangles == b.triangles);
  REQUIRE(a.vertices.size() == b.vertices.size());
  for (std::size_t v = 0; v < a.vertices.size(); ++v) {
    for (int k = 0; k < 3; ++k) {
      REQUIRE(std::bit_cast<std::uint64_t>(a.vertices[v][k]) ==
              std::bit_cast<std::uint64_t>(b.vertices[v][k]));
    }
  }
}

}  // namespace

TEST_CASE("binary STL welded by partitions numbers vertices as one weld in file order",
          "[mesh-reader][weld]") {
  for (const std::size_t facets : {1, 5, 21845, 21846, 32768, 100000}) {
    INFO(facets << " facets");
    const std::vector<float> corners = random_corners(facets, facets, facets / 3 + 2);
    const Mesh expected = welded_in_order(corners);
    const std::vector<char> bytes = binary_stl(corners);
    for (const int threads : {1, 2, 3}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      check_same(parse_mesh(bytes, "part.stl"), expected);
    }
  }
}

TEST_CASE("a vertex keeps its first corner's zero sign", "[mesh-reader][weld]") {
  std::vector<float> corners = random_corners(7, 70000, 5000);
  // Point a first with +0 in the first block, then with -0 in the third; point b first with
  // -0 in the second block, then with +0 in the third (coordinates off the pool's lattice).
  const auto put = [&](std::size_t facet, float zero, float y) {
    const float corner[3] = {zero, y, 0.1f};
    std::memcpy(&corners[9 * facet], corner, sizeof corner);
  };
  put(100, 0.0f, 0.1f);
  put(66000, -0.0f, 0.1f);
  put(40000, -0.0f, 0.3f);
  put(69000, 0.0f, 0.3f);
  const Mesh mesh = parse_mesh(binary_stl(corners), "part.stl");
  check_same(mesh, welded_in_order(corners));
  CHECK(mesh.triangles[100][0] == mesh.triangles[66000][0]);
  CHECK(mesh.triangles[40000][0] == mesh.triangles[69000][0]);
  CHECK_FALSE(std::signbit(mesh.vertices[mesh.triangles[100][0]][0]));
  CHECK(std::signbit(mesh.vertices[mesh.triangles[40000][0]][0]));
}

TEST_CASE("a non-finite coordinate is named at its first facet, in any block",
          "[mesh-reader][weld]") {
  std::vector<float> corners = random_corners(3, 100000, 30000);
  corners[9 * 99000 + 4] = std::numeric_limits<float>::infinity();
  corners[9 * 70001 + 8] = std::numeric_limits<float>::quiet_NaN();
  corners[9 * 70002] = std::numeric_limits<float>::quiet_NaN();
  const std::vector<char> bytes = binary_stl(corners);
  for (const int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    CHECK_THROWS_WITH(parse_mesh(bytes, "part.stl"),
                      Catch::Contains("triangle 70001 has a NaN or infinite coordinate"));
  }
}
