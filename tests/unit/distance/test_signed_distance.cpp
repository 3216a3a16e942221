// The distance step: the grid search against brute force to the last bit, analytic
// distances and signs around a box, signs at the sharp concave and convex edges and
// corners of a pocket with every method, open and inward nominals, thread-count
// invariance, far-from-origin precision, statistics, progress and input checks.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <numeric>
#include <optional>
#include <random>
#include <thread>

#include <tbb/global_control.h>

#include "distance/signed_distance.hpp"
#include "geometry/closest_point.hpp"
#include "nominal_fixtures.hpp"
#include "search/grid_builder.hpp"
#include "search/indexed_reference.hpp"
#include "search/search_index.hpp"
#include "util/error.hpp"

namespace {

using ncv::SignMethod;
using ncv::Vec3;
namespace fx = ncv::fixtures;

// Over the reference's grid, or by brute force.
ncv::DistanceField distances(const ncv::IndexedReference& reference, bool grid,
                             const std::vector<Vec3>& points, SignMethod method,
                             ncv::SearchStatistics* stats = nullptr) {
  if (!grid) {
    return ncv::compute_signed_distances(*reference.surface, points, {}, method, stats);
  }
  const ncv::SearchIndex index(reference);
  return ncv::compute_signed_distances(index, points, {}, method, stats);
}

// Query points of every kind around a mesh: on it, just off it, inside its box, far out,
// and outside the grid.
std::vector<Vec3> mixed_points(std::mt19937_64& rng, const ncv::Mesh& mesh, std::size_t count) {
  const ncv::BoundingBox box = ncv::bounding_box(mesh);
  const Vec3 extent = box.extent();
  std::vector<Vec3> points;
  for (std::size_t i = 0; points.size() < count; ++i) {
    const std::size_t t = i % mesh.triangle_count();
    switch (i % 8) {
      case 0:
        points.push_back(fx::random_point_on(rng, mesh, t));
        break;
      case 1:
        points.push_back(mesh.corner(t, static_cast<int>(i % 3)));
        break;
      case 2:
        points.push_back(fx::random_point_on(rng, mesh, t) +
                         1e-3 * ncv::norm(extent) * fx::random_direction(rng));
        break;
      case 3:
        points.push_back(fx::random_point(rng, box.min - 0.5 * extent, box.max + 0.5 * extent));
        break;
      case 4:
        points.push_back(fx::random_point(rng, box.min - 5.0 * extent, box.max + 5.0 * extent));
        break;
      case 5:
        points.push_back(box.center() + 1e3 * ncv::norm(extent) * fx::random_direction(rng));
        break;
      case 6:
        points.push_back(0.5 * (mesh.corner(t, 0) + mesh.corner(t, 1)));
        break;
      default:
        points.push_back(fx::random_point(rng, box.min, box.max));
        break;
    }
  }
  return points;
}

// The closest point of a sample on the face the search named.
Vec3 closest_on_face(const ncv::Mesh& mesh, std::uint32_t face, const Vec3& p) {
  return ncv::closest_point_on_triangle(p, mesh.corner(face, 0), mesh.corner(face, 1),
                                        mesh.corner(face, 2))
      .point;
}

void require_identical(const ncv::DistanceField& a, const ncv::DistanceField& b) {
  REQUIRE(a.distance.size() == b.distance.size());
  for (std::size_t i = 0; i < a.distance.size(); ++i) {
    INFO("point " << i);
    REQUIRE(std::bit_cast<std::uint64_t>(a.distance[i]) ==
            std::bit_cast<std::uint64_t>(b.distance[i]));
    REQUIRE(a.closest_face[i] == b.closest_face[i]);
  }
}

void require_grid_equals_brute_force(const ncv::Mesh& mesh, std::mt19937_64& rng, std::size_t count,
                                     SignMethod method) {
  const ncv::IndexedReference nominal = ncv::index_reference(mesh, "nominal");
  const std::vector<Vec3> points = mixed_points(rng, mesh, count);
  const ncv::DistanceField reference = distances(nominal, false, points, method);
  const double base = ncv::default_cell_size(*nominal.surface);
  for (double factor : {1.0, 0.3, 4.0}) {
    ncv::GridOptions options;
    options.cell_size = base * factor;
    INFO("cell size factor " << factor);
    require_identical(
        distances(ncv::index_reference(mesh, "nominal", options), true, points, method), reference);
  }
}

// Points 0.01 from the surface of a voxel solid, many of them near its edges and corners:
// off every triangle along its normal, around every vertex and around edge points.
std::vector<Vec3> points_around(const ncv::Mesh& mesh, std::mt19937_64& rng, double offset) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Vec3> points;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const Vec3 a = mesh.corner(t, 0), b = mesh.corner(t, 1), c = mesh.corner(t, 2);
    const Vec3 n = ncv::normalized(ncv::cross(b - a, c - a));
    for (int i = 0; i < 6; ++i) {
      // Barycentric points crowding the triangle's edges and corners.
      const double u = std::pow(unit(rng), 3.0), v = (1 - u) * std::pow(unit(rng), 3.0);
      const Vec3 on = a + u * (b - a) + v * (c - a);
      points.push_back(on + offset * n);
      points.push_back(on - offset * n);
    }
    for (int i = 0; i < 4; ++i) {
      points.push_back(a + offset * fx::random_direction(rng));
      points.push_back(a + unit(rng) * (b - a) + offset * fx::random_direction(rng));
    }
  }
  return points;
}

// Every sign right against the solid's own inside test (points within 1e-9 of the surface,
// where the sign means nothing, are skipped).
void require_signs(const ncv::DistanceField& field, const std::vector<Vec3>& points,
                   const fx::VoxelSolid& solid, double scale, double offset) {
  std::size_t checked = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = field.distance[i];
    REQUIRE(std::fabs(d) <= offset * (1 + 1e-9));
    if (std::fabs(d) < 1e-9) continue;
    INFO("point " << points[i][0] << " " << points[i][1] << " " << points[i][2] << " d " << d);
    REQUIRE((d < 0) == solid.contains(points[i], scale));
    ++checked;
  }
  CHECK(checked > points.size() * 9 / 10);
}

}  // namespace

TEST_CASE("grid search equals brute force to the last bit", "[distance]") {
  SECTION("random soups, many seeds") {
    for (std::uint64_t seed = 0; seed < 12; ++seed) {
      std::mt19937_64 rng(seed);
      const std::size_t triangles = 50 + 150 * (seed % 4);
      INFO("seed " << seed);
      require_grid_equals_brute_force(
          fx::random_soup(rng, triangles, 0.05 + 0.1 * static_cast<double>(seed % 3)), rng, 800,
          SignMethod::pseudonormal);
    }
  }
  SECTION("structured meshes") {
    std::mt19937_64 rng(100);
    require_grid_equals_brute_force(fx::torus(3, 1, 40, 20), rng, 3000, SignMethod::automatic);
    require_grid_equals_brute_force(fx::pocketed_block().mesh(0.5), rng, 3000,
                                    SignMethod::automatic);
    require_grid_equals_brute_force(fx::box({-1, -2, -3}, {4, 5, 6}), rng, 1000,
                                    SignMethod::automatic);
  }
  SECTION("a flat mesh, one cell thick") {
    std::mt19937_64 rng(101);
    ncv::Mesh sheet = fx::random_soup(rng, 300, 0.1);
    for (Vec3& v : sheet.vertices) v[2] = 0.25;
    require_grid_equals_brute_force(sheet, rng, 1500, SignMethod::winding);
  }
}

TEST_CASE("ties between triangles go to the lowest index", "[distance]") {
  // Every triangle twice: the copy (higher index) is never the answer, even where the grid
  // meets the copy first.
  ncv::Mesh mesh = fx::torus(3, 1, 24, 12);
  const std::size_t half = mesh.triangle_count();
  for (std::size_t t = 0; t < half; ++t) mesh.triangles.push_back(mesh.triangles[t]);
  std::reverse(mesh.triangles.begin(), mesh.triangles.end());  // copies first, originals last
  const ncv::IndexedReference nominal = ncv::index_reference(mesh, "doubled");
  std::mt19937_64 rng(12);
  const std::vector<Vec3> points = mixed_points(rng, mesh, 2000);
  const ncv::DistanceField brute = distances(nominal, false, points, SignMethod::winding);
  const ncv::DistanceField fast = distances(nominal, true, points, SignMethod::winding);
  require_identical(brute, fast);
  for (std::uint32_t face : fast.closest_face) CHECK(face < half);
}

TEST_CASE("distances and signs around a box are the analytic ones", "[distance]") {
  struct Case {
    Vec3 p{0, 0, 0};
    double distance;
  };
  const Case cases[] = {
      {{0.5, 0.5, 1.3}, 0.3},              // above a face
      {{0.25, -0.5, 0.75}, 0.5},           // beside a face
      {{1.2, 0.5, 1.2}, std::sqrt(0.08)},  // off an edge
      {{-0.3, 0.4, -0.4}, 0.5},            // off an edge
      {{1.1, 1.2, 1.3}, std::sqrt(0.14)},  // off a corner
      {{-1, -1, -1}, std::sqrt(3.0)},      // off a corner
      {{0.5, 0.5, 0.9}, -0.1},             // under a face
      {{0.9, 0.5, 0.95}, -0.05},           // near an edge, inside
      {{0.97, 0.98, 0.99}, -0.01},         // near a corner, inside
      {{0.5, 0.5, 0.5}, -0.5},             // equidistant from all six faces
      {{0.5, 0.5, 1.0}, 0.0},              // on a face
      {{1, 1, 1}, 0.0},                    // on a corner
      {{1, 0.5, 0}, 0.0},                  // on an edge
      {{30, 0.5, 0.5}, 29.0},              // far, outside the grid
  };
  std::vector<Vec3> points;
  for (const Case& c : cases) points.push_back(c.p);
  for (const ncv::Mesh& mesh : {fx::box({0, 0, 0}, {1, 1, 1}), [] {
                                  fx::VoxelSolid fine;
                                  fine.fill(0, 0, 0, 4, 4, 4);
                                  return fine.mesh(0.25);
                                }()}) {
    const ncv::IndexedReference nominal = ncv::index_reference(mesh, "box");
    for (SignMethod method :
         {SignMethod::automatic, SignMethod::pseudonormal, SignMethod::winding}) {
      for (bool grid : {true, false}) {
        const ncv::DistanceField field = distances(nominal, grid, points, method);
        for (std::size_t i = 0; i < points.size(); ++i) {
          INFO("point " << i << " method " << ncv::name_of(ncv::kSignMethodNames, method));
          CHECK(field.distance[i] == Approx(cases[i].distance).margin(1e-14));
          if (cases[i].distance == 0) CHECK_FALSE(std::signbit(field.distance[i]));
          const Vec3 c = closest_on_face(mesh, field.closest_face[i], points[i]);
          CHECK(ncv::norm(points[i] - c) == Approx(std::fabs(cases[i].distance)).margin(1e-14));
        }
      }
    }
  }
}

TEST_CASE("signs at sharp concave and convex edges and corners of a pocket", "[distance]") {
  const fx::VoxelSolid solid = fx::pocketed_block();
  const double scale = 1.0, offset = 0.01;
  const ncv::Mesh mesh = solid.mesh(scale);
  std::mt19937_64 rng(21);
  const std::vector<Vec3> points = points_around(mesh, rng, offset);
  const ncv::IndexedReference nominal = ncv::index_reference(mesh, "pocket");
  REQUIRE(nominal.surface->automatic_sign_method() == SignMethod::pseudonormal);
  for (SignMethod method : {SignMethod::automatic, SignMethod::pseudonormal, SignMethod::winding}) {
    INFO("method " << ncv::name_of(ncv::kSignMethodNames, method));
    require_signs(distances(nominal, true, points, method), points, solid, scale, offset);
  }
  SECTION("the same against the inward-oriented copy, which is flipped back") {
    const ncv::IndexedReference inward = ncv::index_reference(fx::flipped(mesh), "inward");
    REQUIRE(inward.surface->flipped());
    REQUIRE(inward.surface->automatic_sign_method() == SignMethod::pseudonormal);
    for (SignMethod method : {SignMethod::automatic, SignMethod::winding}) {
      require_signs(distances(inward, true, points, method), points, solid, scale, offset);
    }
  }
}

TEST_CASE("an open nominal is signed by the winding number", "[distance]") {
  // The pocketed block without one unit square of its bottom (z = 0, x, y in [0, 1]).
  const fx::VoxelSolid solid = fx::pocketed_block();
  ncv::Mesh mesh = solid.mesh(1.0);
  std::erase_if(mesh.triangles, [&](const ncv::Triangle& t) {
    for (std::uint32_t v : t) {
      const Vec3 p = mesh.vertices[v];
      if (p[2] != 0 || p[0] > 1 || p[1] > 1) return false;
    }
    return true;
  });
  REQUIRE(mesh.triangle_count() == solid.mesh(1.0).triangle_count() - 2);
  const ncv::IndexedReference nominal = ncv::index_reference(mesh, "open");
  CHECK(nominal.surface->automatic_sign_method() == SignMethod::winding);
  std::mt19937_64 rng(31);
  std::vector<Vec3> points;
  for (Vec3 p : points_around(mesh, rng, 0.01)) {
    if (p[2] > 0.5) points.push_back(p);  // away from the hole
  }
  require_signs(distances(nominal, true, points, SignMethod::automatic), points, solid, 1.0, 0.01);
}

TEST_CASE("the paper's sign follows the sample normal", "[distance]") {
  const ncv::IndexedReference nominal = ncv::index_reference(fx::box({0, 0, 0}, {1, 1, 1}), "box");
  const std::vector<Vec3> points = {
      {0.5, 0.5, 1.2}, {0.5, 0.5, 1.2}, {0.5, 0.5, 0.8}, {0.5, 0.5, 1.2}, {0.5, 0.5, 1.0}};
  const std::vector<Vec3> normals = {{0, 0, 1}, {0, 0, -1}, {0, 0, 1}, {0, 0, 0}, {0, 0, -1}};
  const ncv::DistanceField field =
      ncv::compute_signed_distances(*nominal.surface, points, normals, SignMethod::paper);
  CHECK(field.distance[0] == Approx(0.2));
  CHECK(field.distance[1] == Approx(-0.2));
  CHECK(field.distance[2] == Approx(-0.2));  // inside, but the paper only asks N_p
  CHECK(field.distance[3] == Approx(-0.2));  // no normal: not positive
  CHECK(field.distance[4] == 0.0);
  CHECK_FALSE(std::signbit(field.distance[4]));
  CHECK_THROWS_AS(ncv::compute_signed_distances(*nominal.surface, points, {}, SignMethod::paper),
                  ncv::UsageError);
}

TEST_CASE("where a pseudonormal vanishes the exact winding number decides", "[distance]") {
  // A triangle covered twice with opposite orientations: closed and consistent, but every
  // edge and vertex pseudonormal is zero. Points in its plane, off its edges and corners,
  // are outside.
  ncv::Mesh sheet;
  sheet.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  sheet.triangles = {{0, 1, 2}, {0, 2, 1}};
  const ncv::IndexedReference nominal = ncv::index_reference(sheet, "sheet");
  const std::vector<Vec3> points = {{0.5, -0.5, 0}, {1, 1, 0}, {-0.5, 0.5, 0}, {2, -1, 0}};
  const ncv::DistanceField field = distances(nominal, false, points, SignMethod::pseudonormal);
  for (double d : field.distance) CHECK(d > 0);
}

TEST_CASE("results do not depend on the thread count", "[distance]") {
  const ncv::Mesh mesh = fx::torus(3, 1, 80, 40);
  const ncv::IndexedReference nominal = ncv::index_reference(mesh, "torus");
  std::mt19937_64 rng(41);
  const std::vector<Vec3> points = mixed_points(rng, mesh, 16000);
  for (SignMethod method : {SignMethod::pseudonormal, SignMethod::winding}) {
    const auto run = [&](int threads, ncv::SearchStatistics& stats) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      return distances(nominal, true, points, method, &stats);
    };
    ncv::SearchStatistics one_stats, two_stats;
    const ncv::DistanceField one = run(1, one_stats);
    const ncv::DistanceField two = run(2, two_stats);
    require_identical(one, two);
    CHECK(one_stats.triangles_tested == two_stats.triangles_tested);
    CHECK(one_stats.cells_visited == two_stats.cells_visited);
    CHECK(one_stats.queries == two_stats.queries);
  }
}

TEST_CASE("the points measured in another order get the same values", "[distance]") {
  const ncv::Mesh mesh = fx::torus(3, 1, 80, 40);
  const ncv::IndexedReference nominal = ncv::index_reference(mesh, "torus");
  const ncv::SearchIndex index(nominal);
  const ncv::SideRule side(*nominal.surface, SignMethod::pseudonormal);
  std::mt19937_64 rng(43);
  const std::vector<Vec3> points = mixed_points(rng, mesh, 6000);
  const ncv::DistanceField reference = distances(nominal, false, points, SignMethod::pseudonormal);
  // The last 5,000 points in random order, after the first 1,000 in theirs, on 1 and 2
  // threads; then the whole set reversed.
  std::vector<std::uint32_t> order(5000);
  std::iota(order.begin(), order.end(), 1000u);
  std::shuffle(order.begin(), order.end(), rng);
  for (const int threads : {1, 2}) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    require_identical(ncv::compute_signed_distances(index, points, {}, side, nullptr, {}, order),
                      reference);
  }
  std::vector<std::uint32_t> reversed(points.size());
  std::iota(reversed.rbegin(), reversed.rend(), 0u);
  require_identical(ncv::compute_signed_distances(index, points, {}, side, nullptr, {}, reversed),
                    reference);
  // An unusable point is named by its own number whatever its place.
  std::vector<Vec3> bad = points;
  bad[4000] = bad[5500] = Vec3{std::nan(""), 0, 0};
  CHECK_THROWS_WITH(ncv::compute_signed_distances(index, bad, {}, side, nullptr, {}, order),
                    Catch::Contains("point 4000 "));
  const std::vector<std::uint32_t> too_long(points.size() + 1, 0);
  CHECK_THROWS_AS(ncv::compute_signed_distances(index, points, {}, side, nullptr, {}, too_long),
                  ncv::UsageError);
}

TEST_CASE("a part far from the origin keeps its precision", "[distance]") {
  const Vec3 shift{1e6, 0, 0};
  const ncv::Mesh mesh = fx::torus(3, 1, 60, 30);
  const ncv::IndexedReference here = ncv::index_reference(mesh, "here");
  const ncv::IndexedReference there = ncv::index_reference(fx::translated(mesh, shift), "there");
  std::mt19937_64 rng(51);
  std::vector<Vec3> points = points_around(mesh, rng, 0.01);
  std::vector<Vec3> shifted = points;
  for (Vec3& p : shifted) p += shift;
  const ncv::DistanceField a = distances(here, true, points, SignMethod::automatic);
  const ncv::DistanceField b = distances(there, true, shifted, SignMethod::automatic);
  for (std::size_t i = 0; i < points.size(); ++i) {
    // Coordinates near 1e6 are spaced 1.2e-10 apart: that is all that may differ (a
    // closest point slides a little more where the surface curves away).
    REQUIRE(b.distance[i] == Approx(a.distance[i]).margin(1e-9));
    // The faces may differ where the closest point is on an edge (a tie); the point may not.
    const Vec3 on_a = closest_on_face(mesh, a.closest_face[i], points[i]);
    const Vec3 on_b = closest_on_face(fx::translated(mesh, shift), b.closest_face[i], shifted[i]);
    REQUIRE(ncv::norm(on_b - shift - on_a) < 1e-8);
  }
}

TEST_CASE("search statistics count queries, triangles and cells", "[distance]") {
  const ncv::Mesh mesh = fx::torus(3, 1, 40, 20);
  const ncv::IndexedReference nominal = ncv::index_reference(mesh, "torus");
  std::mt19937_64 rng(61);
  std::vector<Vec3> points;
  for (int i = 0; i < 500; ++i) {
    points.push_back(fx::random_point_on(rng, mesh, static_cast<std::size_t>(i)) +
                     0.01 * fx::random_direction(rng));
  }
  ncv::SearchStatistics brute, fast;
  distances(nominal, false, points, SignMethod::automatic, &brute);
  distances(nominal, true, points, SignMethod::automatic, &fast);
  CHECK(brute.queries == 500);
  CHECK(brute.triangles_tested == 500 * mesh.triangle_count());
  CHECK(brute.cells_visited == 0);
  CHECK(brute.triangles_per_query() == Approx(static_cast<double>(mesh.triangle_count())));
  CHECK(fast.queries == 500);
  // Queries searched together share the cells they read: some, fewer than one a query.
  CHECK(fast.cells_visited > 0);
  CHECK(fast.cells_visited < 500);
  CHECK(fast.triangles_per_query() >= 1);
  CHECK(fast.triangles_per_query() < 0.1 * static_cast<double>(mesh.triangle_count()));
}

TEST_CASE("progress is reported from the calling thread, ending at the total", "[distance]") {
  const ncv::IndexedReference nominal = ncv::index_reference(fx::torus(3, 1, 40, 20), "torus");
  const ncv::SearchIndex search(nominal);
  std::mt19937_64 rng(71);
  std::vector<Vec3> points;
  for (int i = 0; i < 20000; ++i) points.push_back(fx::random_point(rng, {-5, -5, -2}, {5, 5, 2}));
  std::vector<std::pair<std::size_t, std::size_t>> calls;
  bool other_thread = false;
  const auto caller = std::this_thread::get_id();
  ncv::compute_signed_distances(search, points, {}, SignMethod::automatic, nullptr,
                                [&](std::size_t done, std::size_t total) {
                                  other_thread |= std::this_thread::get_id() != caller;
                                  calls.emplace_back(done, total);
                                });
  CHECK_FALSE(other_thread);
  REQUIRE_FALSE(calls.empty());
  CHECK(calls.back() == std::pair<std::size_t, std::size_t>{points.size(), points.size()});
  for (std::size_t i = 1; i < calls.size(); ++i) CHECK(calls[i].first >= calls[i - 1].first);
}

TEST_CASE("unusable query points are refused", "[distance]") {
  const ncv::IndexedReference nominal = ncv::index_reference(fx::box({0, 0, 0}, {1, 1, 1}), "box");
  for (Vec3 bad : {Vec3{std::nan(""), 0, 0}, Vec3{0, std::numeric_limits<double>::infinity(), 0},
                   Vec3{0, 0, 2e100}}) {
    const std::vector<Vec3> points = {{0.5, 0.5, 2}, bad};
    CHECK_THROWS_AS(distances(nominal, false, points, SignMethod::automatic), ncv::InputError);
  }
  CHECK(distances(nominal, false, {}, SignMethod::automatic).distance.empty());
}
