#include <catch2/catch.hpp>

#include <random>

#include "geometry/triangle_distance.hpp"
#include "nominal_fixtures.hpp"

namespace ncv {
namespace {

// The least distance between two triangles over a dense grid of points on the first, each
// measured exactly to the second: an upper estimate of their distance.
double sampled_distance(const TriangleCorners& a, const TriangleCorners& b, int steps) {
  double least = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= steps; ++i) {
    for (int j = 0; i + j <= steps; ++j) {
      const Vec3 p = fixtures::point_on(a, double(i) / steps, double(j) / steps);
      least = std::min(least, std::sqrt(closest_point_on_triangle(p, b).squared_distance));
    }
  }
  return least;
}

TriangleCorners random_triangle(std::mt19937_64& rng, Vec3 centre, double size) {
  std::uniform_real_distribution<double> u(-size, size);
  return {centre + Vec3(u(rng), u(rng), u(rng)), centre + Vec3(u(rng), u(rng), u(rng)),
          centre + Vec3(u(rng), u(rng), u(rng))};
}

}  // namespace

TEST_CASE("segment distance is the least over dense points of both segments",
          "[triangle_distance]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 p1(u(rng), u(rng), u(rng)), q1(u(rng), u(rng), u(rng));
    const Vec3 p2(u(rng), u(rng), u(rng)), q2 = trial % 10 == 0 ? p2 : Vec3(u(rng), u(rng), u(rng));
    double sampled = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 200; ++i) {
      for (int j = 0; j <= 200; ++j) {
        const Vec3 a = p1 + (i / 200.0) * (q1 - p1), b = p2 + (j / 200.0) * (q2 - p2);
        sampled = std::min(sampled, norm(a - b));
      }
    }
    const double exact = std::sqrt(segment_squared_distance(p1, q1, p2, q2));
    CHECK(exact <= sampled + 1e-12);
    CHECK(exact >= sampled - 0.02);  // the grid's spacing, 2/200 along each segment
  }
}

TEST_CASE("the triangle distance bound never exceeds the true distance and is tight apart",
          "[triangle_distance]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> offset(0, 3);
  int separated = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const TriangleCorners a = random_triangle(rng, Vec3(0, 0, 0), 1);
    const TriangleCorners b = random_triangle(rng, Vec3(offset(rng), 0, 0), 1);
    const double bound = triangle_distance_lower_bound(a, b, 1e-12);
    const double sampled = std::min(sampled_distance(a, b, 60), sampled_distance(b, a, 60));
    CHECK(bound <= sampled + 1e-12);
    if (bound > 0) {
      ++separated;
      // Dense points on both triangles 1/60 of their size apart reach the closest pair to
      // within that spacing.
      CHECK(bound >= sampled - 0.1);
    }
  }
  CHECK(separated > 50);
}

TEST_CASE("triangles that cross or touch get no positive bound", "[triangle_distance]") {
  const TriangleCorners flat = {Vec3(-1, -1, 0), Vec3(2, -1, 0), Vec3(-1, 2, 0)};
  const TriangleCorners piercing = {Vec3(0, 0, -1), Vec3(0.2, 0, 1), Vec3(0, 0.2, 1)};
  const TriangleCorners resting = {Vec3(0, 0, 0), Vec3(0.2, 0, 1), Vec3(0, 0.2, 1)};
  const TriangleCorners above = {Vec3(0, 0, 0.5), Vec3(0.2, 0, 1), Vec3(0, 0.2, 1)};
  CHECK(triangle_distance_lower_bound(flat, piercing, 1e-12) == 0);
  CHECK(triangle_distance_lower_bound(flat, resting, 1e-12) == 0);
  CHECK(triangle_distance_lower_bound(flat, above, 1e-12) == Approx(0.5).margin(1e-9));
  CHECK(triangles_separated(flat, above, 1e-12));
  CHECK_FALSE(triangles_separated(flat, piercing, 1e-12));
}

}  // namespace ncv
