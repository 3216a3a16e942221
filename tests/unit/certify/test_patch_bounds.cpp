#include <catch2/catch.hpp>

#include <random>

#include "certify/patch_bounds.hpp"
#include "nominal_fixtures.hpp"
#include "search/indexed_reference.hpp"
#include "search/search_index.hpp"

namespace ncv {

TEST_CASE("every point of a triangle lies within its covering radius of a corner",
          "[patch_bounds]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 300; ++trial) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    // Every third one obtuse: its third corner over a random point of the first edge, at a
    // random small height (a sliver); the others anywhere.
    const double s = 0.5 * (u(rng) + 1), height = 0.2 * std::pow(10.0, 2 * u(rng) - 1);
    const Vec3 c = trial % 3 == 0 ? (1 - s) * a + s * b + Vec3(0, 0, height * norm(b - a))
                                  : Vec3(u(rng), u(rng), u(rng));
    const double radius = covering_radius(a, b, c);
    double farthest = 0;
    for (int i = 0; i <= 100; ++i) {
      for (int j = 0; i + j <= 100; ++j) {
        const Vec3 p = a + (i / 100.0) * (b - a) + (j / 100.0) * (c - a);
        farthest = std::max(farthest, std::min({norm(p - a), norm(p - b), norm(p - c)}));
      }
    }
    CHECK(farthest <= radius * (1 + 1e-12));
    // Reached, not only bounded: the circumcentre of an acute triangle, where a bisector
    // meets the longest edge of an obtuse one.
    CHECK(farthest >= 0.97 * radius);
  }
}

TEST_CASE("an obtuse triangle's covering radius is reached on its longest edge", "[patch_bounds]") {
  // The apex over the middle of the base: the bisectors of the short edges meet the base at
  // 0.26 from each end (|AC|^2 |AB| / (2 AC.AB) = 0.26 * 1 / 1), a point 0.26 from the apex.
  const Vec3 a(0, 0, 0), b(1, 0, 0);
  CHECK(covering_radius(a, b, Vec3(0.5, 0.1, 0)) == Approx(0.26));
  CHECK(covering_radius(Vec3(0.5, 0.1, 0), a, b) == Approx(0.26));
  // The apex over a quarter of the base: the far end's bisector decides.
  const double far_end = (0.75 * 0.75 + 0.01) / (2 * 0.75);
  CHECK(covering_radius(a, b, Vec3(0.25, 0.1, 0)) == Approx(far_end));
  // A right angle: half the hypotenuse, as the circumradius; the apex on the base (a flat
  // triangle): half the longer part.
  CHECK(covering_radius(a, b, Vec3(0.5, 0.5, 0)) == Approx(0.5));
  CHECK(covering_radius(a, b, Vec3(0.3, 0, 0)) == Approx(0.35));
  // Repeated corners: the segment's half; one point: zero.
  CHECK(covering_radius(a, b, a) == Approx(0.5));
  CHECK(covering_radius(a, a, a) == 0.0);
}

TEST_CASE("the equilateral triangle's covering radius is its circumradius", "[patch_bounds]") {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, std::sqrt(3.0) / 2, 0);
  CHECK(covering_radius(a, b, c) == Approx(1 / std::sqrt(3.0)));
}

TEST_CASE("a triangle's covering radius is at most its longest edge over sqrt(3)",
          "[patch_bounds]") {
  // The lattice pass screens triangles with that bound before the covering radius.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    const double longest =
        std::sqrt(std::max({squared_norm(b - a), squared_norm(c - b), squared_norm(a - c)}));
    CHECK(covering_radius(a, b, c) <= longest / std::sqrt(3.0) * (1 + 1e-12));
  }
}

TEST_CASE("a patch rising from a contact keeps its lower bound near the contact",
          "[patch_bounds]") {
  // The reference: a large face in z = 0, outside above it, so d(p) = p.z over the patch.
  const ncv::Mesh face{{Vec3(-10, -10, 0), Vec3(10, -10, 0), Vec3(0, 10, 0)}, {{0, 1, 2}}};
  const ncv::MeshCorners reference(face);
  Patch patch;
  patch.corners = {PatchCorner{Vec3(0, 0, 0), 0.0, 0}, PatchCorner{Vec3(0.2, 0, 1), 1.0, 0},
                   PatchCorner{Vec3(0, 0.2, 0.5), 0.5, 0}};
  const double slack = 1e-9;
  const double h =
      covering_radius(patch.corners[0].point, patch.corners[1].point, patch.corners[2].point);
  bound_from_corners(patch, reference, slack, true);
  // |d| alone would give -1: the corners' values within h give -h.
  CHECK(patch.upper_abs >= 1.0);
  CHECK(patch.lower() >= -h - 2 * slack);
  CHECK(patch.lower() < -h + 2 * slack);
  CHECK(patch.upper() <= 1.0 + h + 2 * slack);
  // The truth lies inside: d = z from 0 to 1 over the patch.
  CHECK(patch.lower() <= 0.0);
  CHECK(patch.upper() >= 1.0);
  // Without a continuous side no interval on d is known: only |d|.
  bound_from_corners(patch, reference, slack, false);
  CHECK(patch.lower() == -patch.upper_abs);
}

TEST_CASE("gathering near triangles beyond the cell limit reads a small reference whole",
          "[patch_bounds]") {
  // A box of 12 large triangles, gridded by default (finely: grid_builder.hpp), and the
  // reference triangles whose boxes come within `reach` of a box around its corner.
  const IndexedReference box = index_reference(fixtures::box({0, 0, 0}, {8, 4, 2}), "box");
  const SearchIndex index(box);
  NearbyTriangles nearby(index);
  BoundingBox around;
  around.extend(Vec3(-0.5, -0.5, -0.5));
  around.extend(Vec3(0.5, 0.5, 0.5));
  const auto within = [&](double reach) {
    std::vector<std::uint32_t> expected;
    for (std::uint32_t t = 0; t < index.triangles().size(); ++t) {
      if (box_gap(around, BoundingBox::of(index.triangles()[t])) <= reach) expected.push_back(t);
    }
    return expected;
  };
  for (const double reach : {0.1, 1.0, 3.0}) {
    CAPTURE(reach);
    std::vector<std::uint32_t> seen;
    const auto visit = [&](std::uint32_t t) {
      seen.push_back(t);
      return true;
    };
    // Through the cells (no limit), then over a limit the grown box exceeds.
    REQUIRE(nearby.for_each(around, reach, std::uint64_t{1} << 40, visit));
    std::sort(seen.begin(), seen.end());
    CHECK(seen == within(reach));
    seen.clear();
    REQUIRE(nearby.for_each(around, reach, 12, visit));
    CHECK(seen == within(reach));
    // A limit below the triangle count: nothing.
    seen.clear();
    CHECK_FALSE(nearby.for_each(around, reach, 11, visit));
    CHECK(seen.empty());
  }
}

}  // namespace ncv
