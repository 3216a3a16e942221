// The kernel on vectors of points against the scalar kernel, to the last bit of the
// squared distance and the point, and the same feature: random triangles and points,
// collinear and repeated corners, a point triangle, points on corners and edges, parts
// 2e4 from the origin. Two lanes here (this unit is built for the default target); the
// wider builds run the same code through the group search (test_group_search.cpp).
#include <catch2/catch.hpp>

#include <bit>
#include <random>

#include "geometry/closest_point_lanes.hpp"

namespace {

using ncv::Vec3;

ncv::TriangleCorners random_triangle(std::mt19937_64& rng, int kind, double scale, Vec3 shift) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  ncv::TriangleCorners t;
  for (Vec3& corner : t) corner = shift + scale * Vec3(unit(rng), unit(rng), unit(rng));
  switch (kind) {
    case 1:
      t[2] = t[0] + 0.37 * (t[1] - t[0]);  // collinear
      break;
    case 2:
      t[2] = t[1];  // a repeated corner
      break;
    case 3:
      t[1] = t[2] = t[0];  // a point
      break;
    case 4:
      t[2] = t[0] + 1e-9 * (t[2] - t[0]);  // a sliver
      break;
    default:
      break;
  }
  return t;
}

}  // namespace

TEST_CASE("the lanes give the scalar kernel's results to the bit", "[distance]") {
  constexpr int kLanes = 2;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::size_t edges = 0, vertices = 0, faces = 0;
  for (int n = 0; n < 400000; ++n) {
    const double scale = n % 7 == 0 ? 1e4 : 1.0;
    const Vec3 shift = n % 11 == 0 ? Vec3(2e4, -1.5e4, 5e3) : Vec3(0, 0, 0);
    const ncv::TriangleCorners t = random_triangle(rng, n % 6, scale, shift);
    ncv::PointLanes<kLanes> p;
    for (int k = 0; k < kLanes; ++k) {
      Vec3 q = shift + 2 * scale * Vec3(unit(rng), unit(rng), 0.1 * unit(rng));
      if (n % 13 == k) q = t[static_cast<std::size_t>(n % 3)];  // on a corner
      if (n % 17 == k) q = t[0] + 0.5 * (t[1] - t[0]);          // on an edge
      p.x[k] = q[0];
      p.y[k] = q[1];
      p.z[k] = q[2];
    }
    const ncv::TrianglePointLanes<kLanes> lanes =
        ncv::closest_point_on_triangle_lanes<kLanes>(p, ncv::lane_triangle(t));
    for (int k = 0; k < kLanes; ++k) {
      const ncv::TrianglePoint scalar =
          ncv::closest_point_on_triangle(Vec3(p.x[k], p.y[k], p.z[k]), t);
      INFO("case " << n << " lane " << k);
      REQUIRE(std::bit_cast<std::uint64_t>(lanes.squared[k]) ==
              std::bit_cast<std::uint64_t>(scalar.squared_distance));
      REQUIRE(std::bit_cast<std::uint64_t>(lanes.x[k]) ==
              std::bit_cast<std::uint64_t>(scalar.point[0]));
      REQUIRE(std::bit_cast<std::uint64_t>(lanes.y[k]) ==
              std::bit_cast<std::uint64_t>(scalar.point[1]));
      REQUIRE(std::bit_cast<std::uint64_t>(lanes.z[k]) ==
              std::bit_cast<std::uint64_t>(scalar.point[2]));
      REQUIRE(lanes.feature[k] == static_cast<std::int64_t>(scalar.feature));
      edges += ncv::is_edge(scalar.feature);
      vertices += ncv::is_vertex(scalar.feature);
      faces += scalar.feature == ncv::TriangleFeature::face;
    }
  }
  // Every kind of region taken many times.
  CHECK(edges > 10000);
  CHECK(vertices > 10000);
  CHECK(faces > 10000);
}

TEST_CASE("lane helpers: any lane set, square roots", "[distance]") {
  using Lanes = ncv::LaneTypes<2>;
  CHECK_FALSE(ncv::any_lane<2>(Lanes::Mask{0, 0}));
  CHECK(ncv::any_lane<2>(Lanes::Mask{0, -1}));
  CHECK(ncv::any_lane<2>(Lanes::Mask{-1, 0}));
  const Lanes::Real roots = ncv::lane_sqrt<2>(Lanes::Real{2.0, 0.25});
  CHECK(roots[0] == std::sqrt(2.0));
  CHECK(roots[1] == 0.5);
}
