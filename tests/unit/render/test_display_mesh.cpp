// The 3D view's mesh: every sample when it fits, else the telling parts within the budget;
// no value invented, the worst points and the regions kept.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "render/display_mesh.hpp"
#include "sampling/lattice_triangles.hpp"
#include "statistics/error_regions.hpp"
#include "stats_fixtures.hpp"

using ncv::DisplayDetail;
using ncv::DisplayMesh;
using ncv::SampleSet;
using ncv::Tolerance;
using ncv::Vec3;

namespace {

// A dent of depth 0.3 and radius 0.6 around (3.3, 3.6), inside one triangle of a coarse grid.
double dent(Vec3 p) {
  const double r2 = (p[0] - 3.3) * (p[0] - 3.3) + (p[1] - 3.6) * (p[1] - 3.6);
  return r2 < 0.36 ? -0.3 * (1 - r2 / 0.36) : 0.01 * p[0];
}

// Every displayed vertex is a sample (or a vertex without one) with that sample's value.
void check_values_are_samples(const DisplayMesh& display, const SampleSet& samples,
                              const std::vector<double>& d) {
  std::map<std::array<double, 3>, double> value_at;
  for (std::size_t s = 0; s < samples.sample_count(); ++s) {
    const Vec3 p = samples.positions[s];
    value_at[{p[0], p[1], p[2]}] = d[s];
  }
  for (std::size_t v = 0; v < display.mesh.mesh.vertex_count(); ++v) {
    const Vec3 p = display.mesh.mesh.vertices[v];
    const auto found = value_at.find({p[0], p[1], p[2]});
    REQUIRE(found != value_at.end());
    CHECK(found->second == display.mesh.values[v]);
  }
}

bool shows_value(const DisplayMesh& display, double value) {
  return std::find(display.mesh.values.begin(), display.mesh.values.end(), value) !=
         display.mesh.values.end();
}

}  // namespace

TEST_CASE("within the budget the view shows every sample", "[display]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(2, 10.0), 0.5, ncv::SamplingScheme::all);
  const auto d = ncv::test::distances_of(samples, dent);
  const DisplayMesh display =
      ncv::make_display_mesh({samples, d, {}, std::nullopt, {-0.3, 0.1}}, 1'000'000);
  CHECK(display.detail == DisplayDetail::every_sample);
  CHECK(display.mesh.mesh.vertex_count() == samples.sample_count());
  CHECK(display.mesh.mesh.triangle_count() == display.lattice_triangles);
  CHECK_THAT(ncv::describe(display), Catch::Contains("every sample"));
}

TEST_CASE("beyond the budget the worst triangle keeps its lattice", "[display]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(8, 10.0), 0.05, ncv::SamplingScheme::all);
  const auto d = ncv::test::distances_of(samples, dent);
  const Tolerance zone{-0.1, 0.1};
  const ncv::RegionMap regions = ncv::map_error_regions(samples, d, zone);
  REQUIRE(regions.regions.size() == 1);
  const std::uint64_t budget = 3000;
  const DisplayMesh display =
      ncv::make_display_mesh({samples, d, regions.sample_region, zone, {-0.3, 0.1}}, budget);
  REQUIRE(display.lattice_triangles > budget);
  CHECK(display.detail == DisplayDetail::refined);
  CHECK(display.mesh.mesh.triangle_count() <= budget);
  CHECK(display.refined_triangles >= 1);
  // The smallest error, deep inside a triangle, is in the picture with its region.
  const double worst = *std::min_element(d.begin(), d.end());
  CHECK(shows_value(display, worst));
  for (std::size_t v = 0; v < display.mesh.values.size(); ++v) {
    const bool out = display.mesh.values[v] < zone.lower;
    CHECK(display.mesh.regions[v] == (out ? 1u : ncv::kNoRegion));
  }
  check_values_are_samples(display, samples, d);
  CHECK_THAT(ncv::describe(display), Catch::Contains("budget of 3000 triangles"));
}

TEST_CASE("a workpiece beyond the budget is simplified, its regions kept whole", "[display]") {
  // 5000 triangles, each sampled at its corners: the lattice is the mesh itself.
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(50, 10.0), 1.0, ncv::SamplingScheme::all);
  REQUIRE(samples.sample_count() == samples.mesh.vertex_count());
  const auto d = ncv::test::distances_of(samples, dent);
  const Tolerance zone{-0.1, 0.1};
  const ncv::RegionMap regions = ncv::map_error_regions(samples, d, zone);
  REQUIRE(regions.regions.size() == 1);
  const std::uint64_t budget = 1000;
  const DisplayMesh display =
      ncv::make_display_mesh({samples, d, regions.sample_region, zone, {-0.3, 0.1}}, budget);
  CHECK(display.detail == DisplayDetail::clustered);
  CHECK(display.mesh.mesh.triangle_count() <= budget);
  CHECK(display.mesh.mesh.triangle_count() > budget / 2);
  // Every sample of the region is still a vertex, and so is the worst one.
  const auto in_region = static_cast<std::size_t>(
      std::count(display.mesh.regions.begin(), display.mesh.regions.end(), 1u));
  CHECK(in_region == regions.regions[0].samples);
  CHECK(shows_value(display, *std::min_element(d.begin(), d.end())));
  CHECK(shows_value(display, *std::max_element(d.begin(), d.end())));
  check_values_are_samples(display, samples, d);
  CHECK_THAT(ncv::describe(display), Catch::Contains("simplified"));
}
