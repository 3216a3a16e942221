#include <catch2/catch.hpp>

#include <random>

#include "geometry/prism_overlap.hpp"
#include "nominal_fixtures.hpp"

namespace ncv {
namespace {

// The prism over the triangle (0,0,0) (4,0,0) (0,4,0) from z = 1 to z = 3.
const Prism kPrism{{Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(0, 4, 0)}, Vec3(0, 0, 1), 1.0, 3.0};

// Whether a point lies in the closed prism: its height in [low, high] and its shadow in the
// base (a right triangle in z = 0 here).
bool in_prism(Vec3 p) {
  return p[2] >= 1 && p[2] <= 3 && p[0] >= 0 && p[1] >= 0 && p[0] + p[1] <= 4;
}

}  // namespace

TEST_CASE("a triangle meets a prism where it passes through it, not beside or beyond it",
          "[geometry]") {
  const double slack = 1e-9;
  // Crossing the prism's middle height, wider than the prism.
  CHECK(triangle_meets_prism({Vec3(-5, -5, 2), Vec3(10, -5, 2), Vec3(-5, 10, 2)}, kPrism, slack));
  // Piercing it vertically through the base's middle, reaching from below the prism to above.
  CHECK(triangle_meets_prism({Vec3(1, 1, -5), Vec3(1.2, 1, 9), Vec3(1, 1.2, 9)}, kPrism, slack));
  // In the base's own plane, below the prism's low height: the contact the side proof allows.
  CHECK_FALSE(
      triangle_meets_prism({Vec3(-5, -5, 0), Vec3(10, -5, 0), Vec3(-5, 10, 0)}, kPrism, slack));
  // Above its high height, and beside the base's hypotenuse.
  CHECK_FALSE(triangle_meets_prism({Vec3(-5, -5, 3.5), Vec3(10, -5, 3.5), Vec3(-5, 10, 3.5)},
                                   kPrism, slack));
  CHECK_FALSE(triangle_meets_prism({Vec3(3, 3, 0), Vec3(9, 3, 4), Vec3(3, 9, 2)}, kPrism, slack));
  // A wall standing on the hypotenuse's line touches the prism's side: it meets it.
  CHECK(triangle_meets_prism({Vec3(4, 0, 0), Vec3(0, 4, 0), Vec3(2, 2, 5)}, kPrism, slack));
}

TEST_CASE("a triangle said not to meet a prism has no dense point inside it", "[geometry]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-2, 6);
  int apart = 0, meeting = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const TriangleCorners t = {Vec3(coordinate(rng), coordinate(rng), coordinate(rng) - 1),
                               Vec3(coordinate(rng), coordinate(rng), coordinate(rng) - 1),
                               Vec3(coordinate(rng), coordinate(rng), coordinate(rng) - 1)};
    bool inside = false;
    for (int i = 0; i <= 60 && !inside; ++i) {
      for (int j = 0; i + j <= 60 && !inside; ++j)
        inside = in_prism(fixtures::point_on(t, i / 60.0, j / 60.0));
    }
    const bool meets = triangle_meets_prism(t, kPrism, 1e-9);
    if (!meets) CHECK_FALSE(inside);
    apart += meets ? 0 : 1;
    meeting += inside ? 1 : 0;
  }
  // Both kinds occur, so the check above is exercised.
  CHECK(apart > 300);
  CHECK(meeting > 300);
}

}  // namespace ncv
