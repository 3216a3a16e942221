// The group search against brute force, to the last bit, in every build the CPU runs (2, 4
// and 8 lanes): random soups with degenerate triangles, structured meshes, ties, parts far
// from the origin, groups of every size and spread, groups of one point repeated; and the
// spatial order the distance step searches a block in.
#include <catch2/catch.hpp>

#include <bit>
#include <numeric>
#include <random>

#include "nominal_fixtures.hpp"
#include "search/closest_point_search.hpp"
#include "search/grid_builder.hpp"
#include "search/group_search_state.hpp"
#include "search/indexed_reference.hpp"
#include "search/query_order.hpp"
#include "search/search_index.hpp"

namespace {

using ncv::Vec3;
namespace fx = ncv::fixtures;

// Query points of every kind around a mesh, in runs that lie together (as a sampled
// workpiece's do) and runs that do not.
std::vector<Vec3> queries_around(std::mt19937_64& rng, const ncv::Mesh& mesh, std::size_t count) {
  const ncv::BoundingBox box = ncv::bounding_box(mesh);
  const double size = ncv::norm(box.extent());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> points;
  while (points.size() < count) {
    const std::size_t t = points.size() % mesh.triangle_count();
    const Vec3 on = fx::random_point_on(rng, mesh, t);
    const double spread = size * std::pow(10.0, -4 * unit(rng));  // 1e-4 to 1 of the size
    const double off = size * (unit(rng) < 0.3 ? 0.0 : 0.2 * std::pow(unit(rng), 3));
    const Vec3 centre = on + off * fx::random_direction(rng);
    const std::size_t run = 1 + static_cast<std::size_t>(unit(rng) * 40);
    for (std::size_t k = 0; k < run; ++k) {
      switch ((points.size() + k) % 5) {
        case 0:
          points.push_back(mesh.corner(t, static_cast<int>(k % 3)));
          break;
        case 1:
          points.push_back(centre);  // the same point again
          break;
        default:
          points.push_back(centre + spread * unit(rng) * fx::random_direction(rng));
      }
    }
  }
  points.resize(count);
  return points;
}

// A degenerate triangle of every kind among a soup's: a repeated corner, three collinear
// corners, a point.
ncv::Mesh with_degenerate_triangles(ncv::Mesh mesh) {
  const Vec3 a = mesh.vertices[0], b = mesh.vertices[1];
  const auto v = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.push_back(a + 0.5 * (b - a));
  mesh.vertices.push_back(a + 2.0 * (b - a));
  mesh.triangles.push_back({0, 1, 1});
  mesh.triangles.push_back({0, v, 1});
  mesh.triangles.push_back({0, v + 1, v});
  mesh.triangles.push_back({2, 2, 2});
  return mesh;
}

void require_same(const ncv::ClosestHit& a, const ncv::ClosestHit& b) {
  REQUIRE(std::bit_cast<std::uint64_t>(a.squared_distance) ==
          std::bit_cast<std::uint64_t>(b.squared_distance));
  REQUIRE(a.triangle == b.triangle);
  REQUIRE(a.feature == b.feature);
  for (int axis = 0; axis < 3; ++axis) {
    REQUIRE(std::bit_cast<std::uint64_t>(a.point[axis]) ==
            std::bit_cast<std::uint64_t>(b.point[axis]));
  }
}

// Every build of the group search against brute force on the points, in blocks of
// `block` points (each starting afresh, as the distance step's do).
void require_brute_force(const ncv::Mesh& mesh, const std::vector<Vec3>& global, std::size_t block,
                         const ncv::GridOptions& options = {}) {
  const ncv::IndexedReference reference = ncv::index_reference(mesh, "nominal", options);
  const ncv::SearchIndex index(reference);
  std::vector<Vec3> points = global;
  for (Vec3& p : points) p = reference.surface->to_local(p);
  std::vector<ncv::ClosestHit> expected(points.size());
  ncv::SearchCounters brute;
  for (std::size_t i = 0; i < points.size(); ++i) {
    expected[i] = ncv::brute_force_closest(index.triangles(), points[i], brute);
  }
  const std::vector<ncv::GroupSearchBuild> builds = ncv::group_searches_for_cpu();
  REQUIRE(builds.back().name == std::string("sse2"));
  for (const ncv::GroupSearchBuild& build : builds) {
    INFO("build " << build.name);
    ncv::GroupSearcher::State state(index);
    ncv::SearchCounters counters;
    std::vector<ncv::ClosestHit> hits(points.size());
    for (std::size_t begin = 0; begin < points.size(); begin += block) {
      const std::size_t end = std::min(points.size(), begin + block);
      state.forget();
      for (std::size_t k = begin; k < end;) {
        const std::size_t n =
            build.search(state, {points.data() + k, end - k}, {hits.data() + k, end - k}, counters);
        REQUIRE(n >= 1);
        REQUIRE(n <= std::min(ncv::kGroupSize, end - k));
        k += n;
      }
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      INFO("point " << i << " at " << global[i][0] << " " << global[i][1] << " " << global[i][2]);
      require_same(hits[i], expected[i]);
    }
    CHECK(counters.triangles_tested >= points.size());
  }
}

}  // namespace

TEST_CASE("the group search equals brute force to the last bit in every build", "[group]") {
  SECTION("random soups with degenerate triangles, blocks of every length") {
    for (std::uint64_t seed = 0; seed < 8; ++seed) {
      std::mt19937_64 rng(seed);
      INFO("seed " << seed);
      const ncv::Mesh mesh = with_degenerate_triangles(
          fx::random_soup(rng, 60 + 120 * (seed % 3), 0.05 + 0.1 * static_cast<double>(seed % 3)));
      require_brute_force(mesh, queries_around(rng, mesh, 1500), 1 + seed * 37);
    }
  }
  SECTION("structured meshes, the grid's cell varied") {
    std::mt19937_64 rng(20);
    for (const ncv::Mesh& mesh : {fx::torus(3, 1, 40, 20), fx::pocketed_block().mesh(0.5),
                                  fx::box({-1, -2, -3}, {4, 5, 6})}) {
      const double base = ncv::default_cell_size(ncv::ReferenceSurface(mesh, "nominal"));
      for (double factor : {1.0, 0.25, 6.0}) {
        INFO("cell factor " << factor);
        ncv::GridOptions options;
        options.cell_size = base * factor;
        require_brute_force(mesh, queries_around(rng, mesh, 2500), 512, options);
      }
    }
  }
  SECTION("every triangle twice: ties go to the lower index") {
    ncv::Mesh mesh = fx::torus(3, 1, 24, 12);
    const std::size_t half = mesh.triangle_count();
    for (std::size_t t = 0; t < half; ++t) mesh.triangles.push_back(mesh.triangles[t]);
    std::reverse(mesh.triangles.begin(), mesh.triangles.end());
    std::mt19937_64 rng(21);
    require_brute_force(mesh, queries_around(rng, mesh, 3000), 512);
  }
  SECTION("far from the origin") {
    std::mt19937_64 rng(22);
    const ncv::Mesh mesh = fx::translated(fx::torus(3, 1, 40, 20), {2e4, -1.5e4, 5e3});
    require_brute_force(mesh, queries_around(rng, mesh, 3000), 512);
  }
  SECTION("one point many times, and points far outside the grid") {
    const ncv::Mesh mesh = fx::torus(3, 1, 30, 15);
    std::vector<Vec3> points(100, Vec3(0.5, 0.25, 3));
    for (int k = 0; k < 40; ++k) points.push_back(Vec3(1e3 * k, -50, 7));
    require_brute_force(mesh, points, 512);
  }
}

TEST_CASE("the spatial order is a permutation that brings neighbours together", "[group]") {
  // A strip walked to and fro: sixteen consecutive points of the given order span 15 along
  // it, in the spatial order far less.
  std::vector<Vec3> points;
  for (int row = 0; row < 8; ++row) {
    for (int k = 0; k < 64; ++k) points.push_back(Vec3(row % 2 ? 63 - k : k, row, 0));
  }
  std::vector<std::uint16_t> order(points.size());
  ncv::spatial_order(points, order);
  std::vector<std::uint16_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::uint16_t> identity(points.size());
  std::iota(identity.begin(), identity.end(), std::uint16_t{0});
  REQUIRE(sorted == identity);
  const auto mean_group_span = [&](const auto& at) {
    double sum = 0;
    for (std::size_t g = 0; g < points.size(); g += 16) {
      ncv::BoundingBox box;
      for (std::size_t k = g; k < g + 16; ++k) box.extend(at(k));
      sum += box.diagonal();
    }
    return sum / static_cast<double>(points.size() / 16);
  };
  const double given = mean_group_span([&](std::size_t k) { return points[k]; });
  const double spatial = mean_group_span([&](std::size_t k) { return points[order[k]]; });
  CHECK(given >= 15);
  CHECK(spatial < 0.6 * given);
  // The given order is worth ordering for runs that must stay within 10, not within 20.
  CHECK(ncv::runs_lie_apart(points, 16, 10));
  CHECK_FALSE(ncv::runs_lie_apart(points, 16, 20));
  std::vector<Vec3> ordered(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) ordered[k] = points[order[k]];
  CHECK_FALSE(ncv::runs_lie_apart(ordered, 16, 10));

  // The same points give the same order; one point, or all equal, keep their order.
  std::vector<std::uint16_t> again(points.size());
  ncv::spatial_order(points, again);
  CHECK(again == order);
  const std::vector<Vec3> same(20, Vec3(1, 2, 3));
  std::vector<std::uint16_t> kept(same.size());
  ncv::spatial_order(same, kept);
  CHECK(kept == std::vector<std::uint16_t>(identity.begin(), identity.begin() + 20));
}
