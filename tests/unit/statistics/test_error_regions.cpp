#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "sampling/sampling.hpp"
#include "statistics/error_regions.hpp"
#include "statistics/error_statistics.hpp"
#include "stats_fixtures.hpp"

using ncv::ErrorRegion;
using ncv::RegionKind;
using ncv::SampleSet;
using ncv::Tolerance;
using ncv::Vec3;
using ncv::test::distances_of;

namespace {

struct Disc {
  Vec3 centre{0, 0, 0};
  double radius, depth;
};

// A paraboloid dent: -depth at the centre, 0 on the rim and outside.
double dent(const Disc& disc, Vec3 p) {
  const double rho2 = ncv::squared_norm(p - disc.centre) / (disc.radius * disc.radius);
  return rho2 < 1 ? -disc.depth * (1 - rho2) : 0.0;
}

// The square (0,0)-(1,1) plus (0,1.3): two triangles of different area sharing the
// diagonal from (0,0) to (1,1), so their lattices put different points on it.
ncv::Mesh kite() {
  ncv::Mesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1.3, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

}  // namespace

TEST_CASE("two planted gouges give two gouge regions of the right size", "[regions]") {
  const Disc small{{3, 3, 0}, 1.0, 0.2}, large{{7, 6, 0}, 1.5, 0.3};
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(10, 10.0), 0.05, ncv::SamplingScheme::all);
  const auto d = distances_of(samples, [&](Vec3 p) { return dent(small, p) + dent(large, p); });
  const Tolerance zone{-0.01, 0.01};
  const std::vector<ErrorRegion> regions = ncv::find_error_regions(samples, d, zone);
  REQUIRE(regions.size() == 2);

  // Below -0.01 inside the disc of radius r sqrt(1 - 0.01 / depth).
  const auto clipped_area = [&](const Disc& disc) {
    return std::numbers::pi * disc.radius * disc.radius * (1 - 0.01 / disc.depth);
  };
  const ErrorRegion& first = regions[0];
  const ErrorRegion& second = regions[1];
  CHECK(first.kind == RegionKind::gouge);
  CHECK(second.kind == RegionKind::gouge);
  CHECK(first.area == Approx(clipped_area(large)).epsilon(0.005));
  CHECK(second.area == Approx(clipped_area(small)).epsilon(0.005));
  CHECK(first.extreme.value == Approx(-large.depth).epsilon(0.01));
  CHECK(second.extreme.value == Approx(-small.depth).epsilon(0.01));
  CHECK(ncv::norm(first.extreme.position - large.centre) < 0.1);
  CHECK(ncv::norm(second.extreme.position - small.centre) < 0.1);
  CHECK(first.box.min[0] > large.centre[0] - large.radius);
  CHECK(first.box.max[0] < large.centre[0] + large.radius);
  CHECK(first.box.max[0] > large.centre[0] + 0.9 * large.radius);
  CHECK(second.box.min[1] > small.centre[1] - small.radius);
  CHECK(second.box.min[1] < small.centre[1] - 0.9 * small.radius);

  std::uint64_t out_of_tolerance = 0;
  for (double v : d) out_of_tolerance += v < zone.lower;
  CHECK(first.samples + second.samples == out_of_tolerance);
  const ncv::ErrorStatistics stats = ncv::compute_error_statistics(samples, d, zone);
  CHECK(first.area + second.area == Approx(stats.tolerance->gouge).epsilon(1e-12));
}

TEST_CASE("a region across a triangle edge away from the vertices is one region", "[regions]") {
  const SampleSet samples = ncv::sample_mesh(kite(), 0.0065, ncv::SamplingScheme::all);
  REQUIRE(samples.lattice_sizes[0] != samples.lattice_sizes[1]);
  const Disc disc{{0.5, 0.5, 0}, 0.1, 0.2};
  const auto d = distances_of(samples, [&](Vec3 p) { return dent(disc, p); });
  const std::vector<ErrorRegion> regions = ncv::find_error_regions(samples, d, {-0.01, 0.01});
  REQUIRE(regions.size() == 1);
  CHECK(regions[0].kind == RegionKind::gouge);
  CHECK(regions[0].area == Approx(std::numbers::pi * 0.01 * 0.95).epsilon(0.01));
  // It spans both triangles.
  CHECK(regions[0].box.min[0] < 0.45);
  CHECK(regions[0].box.max[0] > 0.55);
}

TEST_CASE("excess and gouge regions are kept apart even where they touch", "[regions]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(4, 4.0), 0.1, ncv::SamplingScheme::all);
  // A linear ramp through zero: excess where x > 2.5, gouge where x < 1.5, and a
  // separate excess bump (peak 0.8) inside the gouge half does not join the excess half.
  const Disc bump{{0.8, 2, 0}, 0.5, -2};
  const auto d = distances_of(samples, [&](Vec3 p) { return p[0] - 2 + dent(bump, p); });
  const std::vector<ErrorRegion> regions = ncv::find_error_regions(samples, d, {-0.5, 0.5});
  REQUIRE(regions.size() == 3);
  CHECK(regions[0].kind == RegionKind::excess);
  CHECK(regions[1].kind == RegionKind::gouge);
  CHECK(regions[2].kind == RegionKind::excess);
  CHECK(regions[0].area == Approx(1.5 * 4).epsilon(1e-12));
  CHECK(regions[0].extreme.value == 2);
  CHECK(regions[0].box.min[0] > 2.5);
  CHECK(regions[2].box.max[0] < 1.3);
  CHECK(regions[0].area > regions[1].area);
  CHECK(regions[1].area > regions[2].area);
}

TEST_CASE("a surface within tolerance has no regions", "[regions]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(3, 1.0), 0.1, ncv::SamplingScheme::all);
  const auto d = distances_of(samples, [](Vec3 p) { return 0.01 * p[0]; });
  CHECK(ncv::find_error_regions(samples, d, {-0.01, 0.01}).empty());
}

TEST_CASE("the region map labels every out-of-tolerance sample with its region", "[regions]") {
  const Disc gouge{{3, 3, 0}, 1.0, 0.2}, bump{{7, 6, 0}, 1.5, -0.3};
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(10, 10.0), 0.1, ncv::SamplingScheme::all);
  const auto d = distances_of(samples, [&](Vec3 p) { return dent(gouge, p) + dent(bump, p); });
  const Tolerance zone{-0.01, 0.01};
  const ncv::RegionMap map = ncv::map_error_regions(samples, d, zone);
  REQUIRE(map.regions.size() == 2);
  CHECK(map.regions[0].kind == RegionKind::excess);  // the larger disc
  CHECK(map.regions[1].kind == RegionKind::gouge);
  // The same regions as find_error_regions, in the same order.
  const std::vector<ErrorRegion> found = ncv::find_error_regions(samples, d, zone);
  REQUIRE(found.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    CHECK(found[k].area == map.regions[k].area);
    CHECK(found[k].extreme.sample == map.regions[k].extreme.sample);
  }
  REQUIRE(map.sample_region.size() == samples.sample_count());
  std::uint64_t counted[3] = {0, 0, 0};
  for (std::uint64_t s = 0; s < samples.sample_count(); ++s) {
    const std::uint32_t label = map.sample_region[s];
    ++counted[label];
    if (ncv::classify(d[s], zone) == ncv::ToleranceClass::within) {
      CHECK(label == ncv::kNoRegion);
      continue;
    }
    REQUIRE(label != ncv::kNoRegion);
    const Disc& disc = map.regions[label - 1].kind == RegionKind::gouge ? gouge : bump;
    CHECK(ncv::norm(samples.positions[s] - disc.centre) < disc.radius);
  }
  CHECK(counted[1] == map.regions[0].samples);
  CHECK(counted[2] == map.regions[1].samples);
  CHECK(map.sample_region[map.regions[0].extreme.sample] == 1);
  CHECK(map.sample_region[map.regions[1].extreme.sample] == 2);
}
