// Generalized winding number: the exact sum on known solids, and the fast hierarchy
// against the exact sum on closed, open and soup meshes, near and far.
#include <catch2/catch.hpp>

#include <numbers>
#include <random>

#include "nominal_fixtures.hpp"
#include "reference/winding_number.hpp"

namespace {

using ncv::Vec3;
namespace fx = ncv::fixtures;

// Largest |fast - exact| over points spread around the mesh's box (and far from it).
double worst_error(const ncv::Mesh& mesh, std::mt19937_64& rng, int points) {
  const ncv::MeshCorners corners(mesh);
  const ncv::WindingNumberTree tree(corners);
  const ncv::BoundingBox box = ncv::bounding_box(mesh);
  const Vec3 pad = 0.3 * box.extent();
  double worst = 0;
  for (int i = 0; i < points; ++i) {
    Vec3 q = fx::random_point(rng, box.min - pad, box.max + pad);
    if (i % 10 == 0) q = q * 20.0;
    if (i % 10 == 1) {  // just off the surface
      q = fx::random_point_on(rng, mesh, i % mesh.triangle_count()) +
          1e-3 * fx::random_direction(rng);
    }
    worst = std::max(worst, std::fabs(tree.evaluate(q) - ncv::winding_number_exact(corners, q)));
  }
  return worst;
}

}  // namespace

TEST_CASE("solid angle of an octant triangle is pi / 2", "[winding]") {
  CHECK(ncv::solid_angle({1, 0, 0}, {0, 1, 0}, {0, 0, 1}) == Approx(std::numbers::pi / 2));
  CHECK(ncv::solid_angle({1, 0, 0}, {0, 0, 1}, {0, 1, 0}) == Approx(-std::numbers::pi / 2));
  CHECK(ncv::solid_angle({5, 0, 0}, {0, 5, 0}, {0, 0, 5}) == Approx(std::numbers::pi / 2));
}

TEST_CASE("exact winding number of a box is 1 inside and 0 outside", "[winding]") {
  const ncv::Mesh box = fx::box({-1, -2, -3}, {1, 2, 3});
  const ncv::MeshCorners corners(box);
  std::mt19937_64 rng(1);
  for (int i = 0; i < 200; ++i) {
    const Vec3 inside = fx::random_point(rng, {-0.99, -1.99, -2.99}, {0.99, 1.99, 2.99});
    CHECK(ncv::winding_number_exact(corners, inside) == Approx(1.0).margin(1e-12));
    const Vec3 outside = fx::random_point(rng, {1.01, -5, -5}, {5, 5, 5});
    CHECK(ncv::winding_number_exact(corners, outside) == Approx(0.0).margin(1e-12));
  }
  const ncv::Mesh inverted = fx::flipped(box);
  CHECK(ncv::winding_number_exact(ncv::MeshCorners(inverted), {0, 0, 0}) ==
        Approx(-1.0).margin(1e-12));
}

TEST_CASE("fast winding number matches the exact sum", "[winding]") {
  std::mt19937_64 rng(4);
  SECTION("closed torus") {
    CHECK(worst_error(fx::torus(3, 1, 64, 32), rng, 3000) < 1e-2);
  }
  SECTION("pocketed block") {
    CHECK(worst_error(fx::pocketed_block().mesh(0.25), rng, 3000) < 1e-2);
  }
  SECTION("open box") {
    ncv::Mesh mesh = fx::pocketed_block().mesh(0.5);
    mesh.triangles.resize(mesh.triangles.size() - 6);
    CHECK(worst_error(mesh, rng, 3000) < 1e-2);
  }
  SECTION("random soup") {
    CHECK(worst_error(fx::random_soup(rng, 4000, 0.05), rng, 2000) < 1e-2);
  }
}

TEST_CASE("fast winding number classifies points around a closed solid", "[winding]") {
  const fx::VoxelSolid solid = fx::pocketed_block();
  const ncv::Mesh mesh = solid.mesh(1.0);
  const ncv::WindingNumberTree tree{ncv::MeshCorners(mesh)};
  std::mt19937_64 rng(8);
  for (int i = 0; i < 5000; ++i) {
    const Vec3 q = fx::random_point(rng, {-1, -1, -1}, {5, 5, 3});
    const double w = tree.evaluate(q);
    // Points on the surface itself have w = 1/2 or so; skip the few within 1e-6 of it.
    const double frac_x = q[0] - std::round(q[0]), frac_y = q[1] - std::round(q[1]),
                 frac_z = q[2] - std::round(q[2]);
    if (std::min({std::fabs(frac_x), std::fabs(frac_y), std::fabs(frac_z)}) < 1e-6) continue;
    CHECK((w >= 0.5) == solid.contains(q, 1.0));
    CHECK(std::fabs(w - std::round(w)) < 1e-2);
  }
}
