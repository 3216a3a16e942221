// The search's float box prefilter: the vector path equals the scalar one lane for lane,
// and a lane is only ever rejected when the exact (long double) distance from the query to
// its box exceeds the bound, at every coordinate scale where the filter is used. Also the
// packing of references into blocks, and the outward rounding of their coordinates.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "nominal_fixtures.hpp"
#include "search/box_lanes.hpp"
#include "search/grid_builder.hpp"

namespace {

using ncv::BoxBlock;
using ncv::kBoxLanes;

long double exact_box_distance(const BoxBlock& block, int lane, const double q[3]) {
  long double sum = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const long double lo = block.lo[axis][lane], hi = block.hi[axis][lane];
    const long double gap = std::max({lo - q[axis], q[axis] - hi, 0.0L});
    sum += gap * gap;
  }
  return std::sqrt(sum);
}

// Random boxes of every size near a random query at coordinate scale `scale`.
struct Case {
  BoxBlock block{};
  double q[3];
  float qf[3];
};

Case random_case(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 0);
  Case c;
  for (int axis = 0; axis < 3; ++axis) {
    c.q[axis] = scale * unit(rng);
    c.qf[axis] = static_cast<float>(c.q[axis]);
  }
  for (int lane = 0; lane < kBoxLanes; ++lane) {
    const double size = scale * std::ldexp(1.0, exponent(rng));
    for (int axis = 0; axis < 3; ++axis) {
      const double centre = c.q[axis] + size * 4 * unit(rng);
      const double half = size * std::fabs(unit(rng));
      c.block.lo[axis][lane] = ncv::float_at_or_below(centre - half);
      c.block.hi[axis][lane] = ncv::float_at_or_above(centre + half);
    }
    c.block.triangle[lane] = static_cast<std::uint32_t>(lane);
  }
  return c;
}

}  // namespace

TEST_CASE("box lanes: the vector path equals the scalar path", "[search]") {
  std::mt19937_64 rng(7);
  for (double scale : {1e-9, 1.0, 250.0, 1e6, 1e15}) {
    for (int k = 0; k < 20000; ++k) {
      const Case c = random_case(rng, scale);
      const float limit = ncv::box_filter_limit(scale * 1e-3 * (k % 7), scale);
      float vector_squared[kBoxLanes], scalar_squared[kBoxLanes];
      const unsigned vector_lanes =
          ncv::near_lanes(c.block, ncv::lane_query(c.qf, limit), vector_squared);
      const unsigned scalar_lanes = ncv::near_lanes_scalar(c.block, c.qf, limit, scalar_squared);
      REQUIRE(vector_lanes == scalar_lanes);
      for (int lane = 0; lane < kBoxLanes; ++lane) {
        REQUIRE(vector_squared[lane] == scalar_squared[lane]);
      }
    }
  }
}

TEST_CASE("box lanes: a rejected box is farther than the bound", "[search]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t rejected = 0, near_misses = 0;
  for (double scale : {0x1p-40, 1e-6, 1.0, 300.0, 1e9, 0x1p60}) {
    REQUIRE(ncv::box_filter_usable(scale));
    for (int k = 0; k < 50000; ++k) {
      const Case c = random_case(rng, scale);
      // Bounds right at a box's distance are where rounding could wrongly reject.
      const int lane_of_bound = k % kBoxLanes;
      const double exact = static_cast<double>(exact_box_distance(c.block, lane_of_bound, c.q));
      const double bound = exact * (1 - 0x1p-18 * unit(rng));
      const float limit = ncv::box_filter_limit(bound, scale);
      float squared[kBoxLanes];
      const unsigned near = ncv::near_lanes(c.block, ncv::lane_query(c.qf, limit), squared);
      for (int lane = 0; lane < kBoxLanes; ++lane) {
        if (near & (1u << lane)) continue;
        ++rejected;
        const long double distance = exact_box_distance(c.block, lane, c.q);
        REQUIRE(distance > bound);
        if (distance < bound + 0x1p-16 * scale) ++near_misses;
      }
    }
  }
  CHECK(rejected > 100000);
  CHECK(near_misses > 0);  // the test does reach bounds within rounding of a box
}

TEST_CASE("box lanes: the filter is switched off outside float's safe range", "[search]") {
  CHECK_FALSE(ncv::box_filter_usable(0x1p-41));
  CHECK_FALSE(ncv::box_filter_usable(0x1p61));
  CHECK_FALSE(ncv::box_filter_usable(1e100));
  CHECK(std::isinf(ncv::box_filter_limit(std::numeric_limits<double>::infinity(), 1.0)));
}

TEST_CASE("reference boxes: block r / 4, lane r % 4 holds reference r's box", "[search]") {
  const ncv::ReferenceSurface nominal(ncv::fixtures::torus(40, 10, 60, 30), "torus");
  const ncv::BackgroundGrid grid = ncv::build_background_grid(nominal);
  const ncv::Buffer<BoxBlock> blocks = ncv::build_reference_boxes(nominal.corners(), grid);
  const std::size_t references = grid.cell_triangles.size();
  REQUIRE(blocks.size() == (references + kBoxLanes - 1) / kBoxLanes);
  for (std::size_t r = 0; r < blocks.size() * kBoxLanes; ++r) {
    const BoxBlock& block = blocks[r / kBoxLanes];
    const int lane = static_cast<int>(r % kBoxLanes);
    if (r >= references) {
      CHECK(block.triangle[lane] == ncv::kPaddingTriangle);
      continue;
    }
    const std::uint32_t t = grid.cell_triangles[r];
    REQUIRE(block.triangle[lane] == t);
    const ncv::TriangleCorners& c = nominal.corners(t);
    for (int axis = 0; axis < 3; ++axis) {
      for (const ncv::Vec3& corner : c) {
        REQUIRE(block.lo[axis][lane] <= corner[axis]);
        REQUIRE(block.hi[axis][lane] >= corner[axis]);
      }
      // The tightest float box: no float between the bound and the nearest corner.
      REQUIRE(block.lo[axis][lane] ==
              ncv::float_at_or_below(std::min({c[0][axis], c[1][axis], c[2][axis]})));
      REQUIRE(block.hi[axis][lane] ==
              ncv::float_at_or_above(std::max({c[0][axis], c[1][axis], c[2][axis]})));
    }
  }
}

TEST_CASE("float_at_or_below / above: the nearest float on that side", "[search]") {
  constexpr float inf = std::numeric_limits<float>::infinity();
  const auto check = [](double x) {
    const float below = ncv::float_at_or_below(x);
    const float above = ncv::float_at_or_above(x);
    INFO("x = " << x);
    REQUIRE(static_cast<double>(below) <= x);
    REQUIRE(static_cast<double>(std::nextafter(below, inf)) > x);
    REQUIRE(static_cast<double>(above) >= x);
    REQUIRE(static_cast<double>(std::nextafter(above, -inf)) < x);
  };
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-160, 140);
  for (int i = 0; i < 200000; ++i) check(std::ldexp(mantissa(random), exponent(random)));
  for (const double x : {0.0, -0.0, 1.0, -1.0, 0.1, -0.1, 1e-50, -1e-50, 1e-40, -1e-40,
                         3.4028234663852886e38, 3.5e38, -3.5e38, 1e100, -1e100}) {
    check(x);
  }
  CHECK(ncv::float_at_or_below(1e-50) == 0.0f);
  CHECK(ncv::float_at_or_above(1e-50) == std::numeric_limits<float>::denorm_min());
  CHECK(ncv::float_at_or_below(-1e-50) == -std::numeric_limits<float>::denorm_min());
  CHECK(ncv::float_at_or_below(1e100) == std::numeric_limits<float>::max());
  CHECK(ncv::float_at_or_above(1e100) == inf);
  CHECK(ncv::float_at_or_below(-1e100) == -inf);
  CHECK(ncv::float_at_or_below(0.5) == 0.5f);
  CHECK(ncv::float_at_or_above(0.5) == 0.5f);
}
