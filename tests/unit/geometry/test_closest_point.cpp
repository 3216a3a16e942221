// The point-triangle kernel against an independent oracle (projection onto the plane when
// it falls inside, else the nearest of the three segments) and on every feature region.
#include <catch2/catch.hpp>

#include <random>

#include "geometry/closest_point.hpp"

namespace {

using ncv::Vec3;

Vec3 closest_on_segment(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 ab = b - a;
  const double length_sq = ncv::squared_norm(ab);
  if (length_sq == 0) return a;
  const double t = std::clamp(ncv::dot(p - a, ab) / length_sq, 0.0, 1.0);
  return a + t * ab;
}

// Squared distance from p to triangle abc computed without Voronoi regions.
double oracle_squared_distance(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 n = ncv::cross(b - a, c - a);
  const double n_sq = ncv::squared_norm(n);
  if (n_sq > 0) {
    const Vec3 q = p - (ncv::dot(p - a, n) / n_sq) * n;
    const double u = ncv::dot(ncv::cross(b - q, c - q), n);
    const double v = ncv::dot(ncv::cross(c - q, a - q), n);
    const double w = ncv::dot(ncv::cross(a - q, b - q), n);
    if (u >= 0 && v >= 0 && w >= 0) return ncv::squared_norm(p - q);
  }
  return std::min({ncv::squared_norm(p - closest_on_segment(p, a, b)),
                   ncv::squared_norm(p - closest_on_segment(p, b, c)),
                   ncv::squared_norm(p - closest_on_segment(p, c, a))});
}

}  // namespace

TEST_CASE("closest point: each Voronoi region gives its feature", "[distance]") {
  const Vec3 a{0, 0, 0}, b{1, 0, 0}, c{0, 1, 0};
  struct Case {
    Vec3 p{0, 0, 0};
    ncv::TriangleFeature feature;
    Vec3 closest{0, 0, 0};
  };
  const Case cases[] = {
      {{-1, -1, 0.5}, ncv::TriangleFeature::vertex0, a},
      {{2, -0.5, 1}, ncv::TriangleFeature::vertex1, b},
      {{-0.5, 2, -1}, ncv::TriangleFeature::vertex2, c},
      {{0.5, -1, 0.25}, ncv::TriangleFeature::edge0, {0.5, 0, 0}},
      {{1, 1, 0.25}, ncv::TriangleFeature::edge1, {0.5, 0.5, 0}},
      {{-1, 0.5, 0}, ncv::TriangleFeature::edge2, {0, 0.5, 0}},
      {{0.25, 0.25, 3}, ncv::TriangleFeature::face, {0.25, 0.25, 0}},
      {{0.25, 0.25, -2}, ncv::TriangleFeature::face, {0.25, 0.25, 0}},
  };
  for (const Case& k : cases) {
    const ncv::TrianglePoint result = ncv::closest_point_on_triangle(k.p, a, b, c);
    CHECK(result.feature == k.feature);
    CHECK(result.point == k.closest);
    CHECK(result.squared_distance == ncv::squared_norm(k.p - k.closest));
  }
}

TEST_CASE("closest point: feature helpers round-trip", "[distance]") {
  for (int k = 0; k < 3; ++k) {
    CHECK(ncv::is_edge(ncv::edge_feature(k)));
    CHECK(ncv::edge_index(ncv::edge_feature(k)) == k);
    CHECK(ncv::is_vertex(ncv::vertex_feature(k)));
    CHECK(ncv::vertex_index(ncv::vertex_feature(k)) == k);
  }
  CHECK_FALSE(ncv::is_edge(ncv::TriangleFeature::face));
  CHECK_FALSE(ncv::is_vertex(ncv::TriangleFeature::face));
}

TEST_CASE("closest point: random triangles agree with the oracle", "[distance]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::uniform_real_distribution<double> spread(-4.0, 4.0);
  const auto random_vec = [&](auto& dist) { return Vec3{dist(rng), dist(rng), dist(rng)}; };
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a = random_vec(coordinate), b = random_vec(coordinate), c = random_vec(coordinate);
    const Vec3 p = random_vec(spread);
    const ncv::TrianglePoint result = ncv::closest_point_on_triangle(p, a, b, c);
    const double expected = oracle_squared_distance(p, a, b, c);
    REQUIRE(result.squared_distance == Approx(expected).epsilon(1e-12).margin(1e-14));
    // The returned point lies on the triangle and is the one measured.
    CHECK(oracle_squared_distance(result.point, a, b, c) <= 1e-24);
    CHECK(result.squared_distance == ncv::squared_norm(p - result.point));
  }
}

TEST_CASE("closest point: degenerate triangles behave as segments and points", "[distance]") {
  const Vec3 o{0, 0, 0}, x1{1, 0, 0}, x2{2, 0, 0};
  const Vec3 p{0.5, 1, 0};
  SECTION("two corners coincide, in every position") {
    for (const auto& [a, b, c] : {std::array{o, o, x1}, std::array{o, x1, o}, std::array{x1, o, o},
                                  std::array{o, x1, x1}}) {
      const ncv::TrianglePoint r = ncv::closest_point_on_triangle(p, a, b, c);
      CHECK(r.squared_distance == 1.0);
      CHECK(r.point == Vec3{0.5, 0, 0});
    }
  }
  SECTION("collinear corners, the middle one anywhere") {
    for (const auto& [a, b, c] : {std::array{o, x1, x2}, std::array{o, x2, x1},
                                  std::array{x1, o, x2}, std::array{x2, x1, o}}) {
      for (const Vec3 q : {Vec3{1.5, 1, 0}, Vec3{3, 0, 1}, Vec3{-1, 0, 0}, Vec3{0.25, 0, 0}}) {
        const ncv::TrianglePoint r = ncv::closest_point_on_triangle(q, a, b, c);
        const Vec3 expected{std::clamp(q[0], 0.0, 2.0), 0, 0};
        CHECK(r.point == expected);
        CHECK(r.squared_distance == ncv::squared_norm(q - expected));
      }
    }
  }
  SECTION("all corners coincide") {
    const ncv::TrianglePoint r = ncv::closest_point_on_triangle(p, x1, x1, x1);
    CHECK(r.point == x1);
    CHECK(r.squared_distance == 1.25);
    CHECK(ncv::is_vertex(r.feature));
  }
}

TEST_CASE("closest point: a point on the triangle is at distance zero", "[distance]") {
  const Vec3 a{1, 2, 3}, b{4, 2, 3}, c{1, 6, 3};
  for (const Vec3 p : {a, b, c, Vec3{2, 3, 3}, Vec3{2.5, 2, 3}, Vec3{1, 4, 3}}) {
    CHECK(ncv::closest_point_on_triangle(p, a, b, c).squared_distance == 0.0);
  }
}
