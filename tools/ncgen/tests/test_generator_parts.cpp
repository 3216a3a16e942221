// Building blocks of the generator: RTIN triangulation, analytic boxes, cutters, sizes.
#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "ncgen/analytic_parts.hpp"
#include "ncgen/cutter.hpp"
#include "ncgen/height_solid.hpp"
#include "ncgen/part_size.hpp"
#include "ncgen/rtin.hpp"
#include "test_generator_checks.hpp"

using namespace ncv::gen;

namespace {

// Two tiles of 16 x 16 cells, 1 mm apart, with a bump that needs refining.
Grid small_grid() {
  return tiled_grid(2, 1, 16.0, 4);
}

std::vector<float> bump_heights(const Grid& grid) {
  std::vector<float> heights(grid.sample_count());
  for (int j = 0; j <= grid.cells_y(); ++j) {
    for (int i = 0; i <= grid.cells_x(); ++i) {
      const double r2 = std::pow(grid.x(i) - 13.0, 2) + std::pow(grid.y(j) - 9.0, 2);
      heights[grid.index(i, j)] = static_cast<float>(2 + 3 * std::exp(-r2 / 8));
    }
  }
  return heights;
}

std::vector<float> propagated(const Grid& grid, const std::vector<float>& heights) {
  std::vector<float> errors = chord_errors(grid, heights);
  propagate_errors(grid, errors);
  return errors;
}

// Twice the signed area of a grid triangle, in cells.
long doubled_area(const Grid& grid, const GridTriangle& t) {
  const auto row = static_cast<std::uint32_t>(grid.samples_x());
  const auto x = [&](int k) { return static_cast<long>(t[k] % row); };
  const auto y = [&](int k) { return static_cast<long>(t[k] / row); };
  return (x(1) - x(0)) * (y(2) - y(0)) - (x(2) - x(0)) * (y(1) - y(0));
}

}  // namespace

TEST_CASE("RTIN extremes: unrefined tiles and the full grid", "[generator]") {
  const Grid grid = small_grid();
  const std::vector<float> none(grid.sample_count(), 0.0f);
  const std::vector<float> all(grid.sample_count(), 1.0f);
  CHECK(rtin_triangles(grid, none, 0.5f).size() == 4);
  const auto full = rtin_triangles(grid, all, 0.5f);
  CHECK(full.size() == 2u * 32 * 16);
  for (const GridTriangle& t : full) REQUIRE(doubled_area(grid, t) == 1);
}

TEST_CASE("RTIN triangles are counter-clockwise, tile the grid and match their count",
          "[generator]") {
  const Grid grid = small_grid();
  const std::vector<float> heights = bump_heights(grid);
  const std::vector<float> errors = propagated(grid, heights);
  for (const float tolerance : {1.0f, 0.1f, 0.01f, 0.001f}) {
    INFO("tolerance " << tolerance);
    const auto triangles = rtin_triangles(grid, errors, tolerance);
    long area = 0;
    for (const GridTriangle& t : triangles) {
      REQUIRE(doubled_area(grid, t) > 0);
      area += doubled_area(grid, t);
    }
    CHECK(area == 2L * grid.cells_x() * grid.cells_y());
    CHECK(triangles.size() == rtin_triangle_count(grid, errors, tolerance));
  }
  CHECK(rtin_triangle_count(grid, errors, 0.001f) > rtin_triangle_count(grid, errors, 0.1f));
}

TEST_CASE("RTIN of a plane needs no refinement", "[generator]") {
  const Grid grid = small_grid();
  std::vector<float> heights(grid.sample_count());
  for (int j = 0; j <= grid.cells_y(); ++j) {
    for (int i = 0; i <= grid.cells_x(); ++i) {
      heights[grid.index(i, j)] = static_cast<float>(0.25 * i - 0.5 * j + 7);
    }
  }
  CHECK(rtin_triangles(grid, propagated(grid, heights), 1e-4f).size() == 4);
}

TEST_CASE("RTIN tolerance for a triangle budget", "[generator]") {
  const Grid grid = tiled_grid(1, 1, 64.0, 6);
  std::vector<float> heights(grid.sample_count());
  for (int j = 0; j <= grid.cells_y(); ++j) {
    for (int i = 0; i <= grid.cells_x(); ++i) {
      heights[grid.index(i, j)] = static_cast<float>(std::sin(0.3 * i) * std::cos(0.2 * j));
    }
  }
  const std::vector<float> errors = propagated(grid, heights);
  for (const std::size_t target : {500u, 2000u, 6000u}) {
    const float tolerance = tolerance_for_count(grid, errors, target);
    const auto count = static_cast<double>(rtin_triangle_count(grid, errors, tolerance));
    CHECK(count == Approx(static_cast<double>(target)).epsilon(0.05));
  }
}

TEST_CASE("height field solids are closed across tiles at any refinement", "[generator]") {
  const Grid grid = small_grid();
  const std::vector<float> heights = bump_heights(grid);
  const std::vector<float> errors = propagated(grid, heights);
  for (const float tolerance : {10.0f, 0.05f, 0.0f}) {
    INFO("tolerance " << tolerance);
    const ncv::Mesh mesh = height_field_solid(grid, heights, errors, tolerance, 0.0);
    CHECK(test::is_sound_solid(test::check_solid(mesh)));
  }
}

TEST_CASE("analytic boxes have the volumes of their offsets", "[generator]") {
  const ncv::Mesh box = box_mesh({0, 0, 0}, {100, 60, 30});
  CHECK(box.triangle_count() == 12);
  CHECK(test::is_sound_solid(test::check_solid(box)));
  CHECK(test::check_solid(box).volume == Approx(100 * 60 * 30));
  const ncv::Mesh offset = box_mesh({-0.1, -0.1, -0.1}, {100.1, 60.1, 30.1});
  CHECK(test::check_solid(offset).volume == Approx(100.2 * 60.2 * 30.2));
}

TEST_CASE("scalloped box rises exactly to the scallop height", "[generator]") {
  const double radius = 1.5;
  const double stepover = 0.625;
  const ncv::Mesh mesh = scalloped_box({100, 60, 30}, radius, stepover, 64);
  const test::SolidReport report = test::check_solid(mesh);
  CHECK(test::is_sound_solid(report));
  const double height = scallop_height(radius, stepover);
  CHECK(height == Approx(radius - std::sqrt(radius * radius - stepover * stepover / 4)));
  const ncv::BoundingBox box = ncv::bounding_box(mesh);
  CHECK(box.max[2] == Approx(30 + height).epsilon(1e-12));
  double lowest_top = INFINITY;
  for (const ncv::Vec3& v : mesh.vertices) {
    if (v[2] > 0) lowest_top = std::min(lowest_top, v[2]);
  }
  CHECK(lowest_top == 30);
  // Area between one arc and its chord at the nominal top, times 96 stepovers and the length.
  const double half = stepover / 2;
  const double arc = stepover * radius - half * std::sqrt(radius * radius - half * half) -
                     radius * radius * std::asin(half / radius);
  CHECK(report.volume - 100 * 60 * 30 == Approx(100 * 96 * arc).epsilon(1e-3));
}

TEST_CASE("scallops need a stepover within the ball", "[generator]") {
  CHECK_THROWS_AS(scalloped_box({10, 10, 10}, 1.0, 2.5, 4), std::invalid_argument);
}

TEST_CASE("cutter clearance keeps the allowance along the normal", "[generator]") {
  const Cutter ball{CutterShape::ball_end, 3.0};
  const Cutter flat{CutterShape::flat_end, 5.0};
  CHECK(cutter_clearance(ball, 0.2, 0) == Approx(0.2));
  CHECK(cutter_clearance(ball, 0.2, 3.2) == Approx(-3.0));
  CHECK(cutter_clearance(flat, 0.3, 4.9) == Approx(0.3));
  CHECK(cutter_clearance(flat, 0.3, 5.3) == Approx(0.0).margin(1e-6));
  CHECK(cutter_surface(ball, 3.0) == Approx(3.0));
  CHECK(cutter_surface(flat, 4.0) == 0);
  const Kernel kernel = surface_kernel(ball, 0.5);
  CHECK(kernel.reach == 6);
  CHECK(kernel.half_width[6] == 6);  // the row through the axis
  CHECK(kernel.rows[6][6] == 0.0f);  // the tip
}

TEST_CASE("sizes by name or factor", "[generator]") {
  CHECK(parse_size("small") == small_size);
  CHECK(parse_size("medium") == medium_size);
  CHECK(parse_size("large") == 1.0);
  CHECK(parse_size("0.5") == 0.5);
  CHECK_THROWS_AS(parse_size("huge"), std::invalid_argument);
  CHECK_THROWS_AS(parse_size("0"), std::invalid_argument);
  CHECK_THROWS_AS(parse_size("2.5"), std::invalid_argument);
  CHECK(zmap_level(small_size) == 9);
  CHECK(zmap_level(large_size) == 10);
}
