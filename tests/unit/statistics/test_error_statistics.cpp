#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <span>
#include <vector>

#include <tbb/global_control.h>

#include "sampling/lattice_triangles.hpp"
#include "sampling/sampling.hpp"
#include "statistics/area_histogram.hpp"
#include "statistics/area_quantiles.hpp"
#include "statistics/error_statistics.hpp"
#include "statistics/verdict.hpp"
#include "stats_fixtures.hpp"
#include "util/error.hpp"

using ncv::compute_error_statistics;
using ncv::ErrorStatistics;
using ncv::SampleSet;
using ncv::Tolerance;
using ncv::Vec3;
using ncv::test::distances_of;

namespace {

double percentile(const ErrorStatistics& stats, double percent) {
  for (const ncv::Percentile& p : stats.percentiles) {
    if (p.percent == percent) return p.value;
  }
  FAIL("percentile " << percent << " not reported");
  return 0;
}

// Ball-end scallop profile: height above the nominal plane of a ball of radius r passing
// every `stepover` along x, the tool centres at x = stepover * (k + 1/2).
double scallop(double x, double r, double stepover) {
  const double u = std::fmod(x, stepover) - stepover / 2;
  return r - std::sqrt(r * r - u * u);
}

// Mean over one period: (1/s) times the integral of r - sqrt(r^2 - u^2) over [-s/2, s/2].
double scallop_mean(double r, double s) {
  const double h = s / 2;
  return r - (h * std::sqrt(r * r - h * h) + r * r * std::asin(h / r)) / s;
}

// A polygon vertex with the interpolated value there.
struct ValuedPoint {
  Vec3 p{0, 0, 0};
  double value;
};

double polygon_area(const std::vector<ValuedPoint>& polygon) {
  Vec3 twice{0, 0, 0};
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    twice += ncv::cross(polygon[k].p - polygon[0].p, polygon[k + 1].p - polygon[0].p);
  }
  return 0.5 * ncv::norm(twice);
}

// Sutherland-Hodgman: the part of the polygon where sign * (value - level) > 0.
std::vector<ValuedPoint> clip(const std::vector<ValuedPoint>& polygon, double level, double sign) {
  std::vector<ValuedPoint> out;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const ValuedPoint& a = polygon[k];
    const ValuedPoint& b = polygon[(k + 1) % polygon.size()];
    const double fa = sign * (a.value - level), fb = sign * (b.value - level);
    if (fa > 0) out.push_back(a);
    if ((fa > 0) != (fb > 0) && fa != fb) {
      const double t = fa / (fa - fb);
      out.push_back({a.p + t * (b.p - a.p), a.value + t * (b.value - a.value)});
    }
  }
  return out;
}

// The measures recomputed the plain way: every sub-triangle built from the positions of
// its lattice points, its area from the cross product, its clipped parts as polygons.
struct Reference {
  double area = 0, integral = 0, squares = 0, excess = 0, gouge = 0;
};

Reference reference_measures(const SampleSet& samples, const std::vector<double>& d,
                             const Tolerance& zone) {
  Reference ref;
  const ncv::Mesh& mesh = samples.mesh;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const std::uint32_t n = samples.lattice_sizes[t];
    if (n < 2) continue;
    const Vec3 a = mesh.corner(t, 0), b = mesh.corner(t, 1), c = mesh.corner(t, 2);
    const auto point = [&](std::uint32_t i, std::uint32_t j) {
      const Vec3 p = a + (double(i) / (n - 1)) * (b - a) + (double(j) / (n - 1)) * (c - a);
      const std::uint64_t s = samples.sample_at(t, i, j);
      REQUIRE(ncv::norm(samples.positions[s] - p) < 1e-12);
      return ValuedPoint{p, d[s]};
    };
    const auto add = [&](ValuedPoint p, ValuedPoint q, ValuedPoint r) {
      const double area = polygon_area({p, q, r});
      ref.area += area;
      ref.integral += area * (p.value + q.value + r.value) / 3;
      // Quadrature exact for quadratics: the edge midpoints, weight area/3 each.
      for (auto [u, v] : {std::pair{p.value, q.value}, {q.value, r.value}, {r.value, p.value}}) {
        ref.squares += area / 3 * ((u + v) / 2) * ((u + v) / 2);
      }
      ref.excess += polygon_area(clip({p, q, r}, zone.upper, +1));
      ref.gouge += polygon_area(clip({p, q, r}, zone.lower, -1));
    };
    for (std::uint32_t i = 0; i + 1 < n; ++i) {
      for (std::uint32_t j = 0; i + j + 1 < n; ++j) {
        add(point(i, j), point(i + 1, j), point(i, j + 1));
        if (i + j + 2 < n) add(point(i + 1, j), point(i, j + 1), point(i + 1, j + 1));
      }
    }
  }
  return ref;
}

// A wavy grid whose cells grow quadratically along x, so lattice sizes range from 2
// (corners only) to several.
ncv::Mesh uneven_surface() {
  ncv::Mesh mesh = ncv::test::flat_grid(12, 1.0);
  for (Vec3& v : mesh.vertices) {
    v[0] = v[0] * v[0] * 4;
    v[2] = 0.3 * std::sin(2 * v[0]) * std::cos(3 * v[1]);
  }
  return mesh;
}

// Each reported percentile p has the fraction p / 100 of the area at or below it (and below
// it: the field has no atoms), summed patch by patch with the closed forms.
// Every lattice patch of the distances d, made at once.
std::vector<ncv::LinearPatch> all_patches(const SampleSet& samples, std::span<const double> d) {
  const ncv::LatticePatches source(samples, d);
  std::vector<ncv::LinearPatch> patches(source.size());
  (void)source.range(0, patches.size(), patches);
  return patches;
}

void check_percentiles_invert(const ErrorStatistics& stats,
                              std::span<const ncv::LinearPatch> patches) {
  for (const ncv::Percentile& p : stats.percentiles) {
    INFO("percentile " << p.percent);
    double at_most = 0, below = 0;
    for (const ncv::LinearPatch& patch : patches) {
      at_most += ncv::area_at_most(patch, p.value);
      below += ncv::area_below(patch, p.value);
    }
    CHECK(at_most / stats.sampled_area == Approx(p.percent / 100).epsilon(1e-9));
    CHECK(below / stats.sampled_area == Approx(p.percent / 100).epsilon(1e-9));
  }
}

}  // namespace

TEST_CASE("a linear field has exact mean, RMS, spread and percentiles", "[stats]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(3, 1.0), 0.07, ncv::SamplingScheme::all);
  // On the unit square, d = x + y has mean 1, variance 1/6, and area fraction
  // t^2/2 below t <= 1.
  const auto d = distances_of(samples, [](Vec3 p) { return p[0] + p[1]; });
  const ErrorStatistics stats = compute_error_statistics(samples, d, std::nullopt);
  CHECK(stats.sampled_area == Approx(1).epsilon(1e-14));
  CHECK(stats.workpiece_area == Approx(1).epsilon(1e-14));
  CHECK(stats.mean == Approx(1).epsilon(1e-13));
  CHECK(stats.std_dev == Approx(std::sqrt(1.0 / 6)).epsilon(1e-13));
  CHECK(stats.rms == Approx(std::sqrt(7.0 / 6)).epsilon(1e-13));
  CHECK(stats.min.value == 0);
  CHECK(stats.max.value == 2);
  CHECK(stats.max.position == Vec3{1, 1, 0});
  CHECK(stats.max_abs.value == 2);
  CHECK(percentile(stats, 1) == Approx(std::sqrt(0.02)).epsilon(1e-12));
  CHECK(percentile(stats, 5) == Approx(std::sqrt(0.1)).epsilon(1e-12));
  CHECK(percentile(stats, 50) == Approx(1).epsilon(1e-12));
  CHECK(percentile(stats, 95) == Approx(2 - std::sqrt(0.1)).epsilon(1e-12));
  CHECK(percentile(stats, 99) == Approx(2 - std::sqrt(0.02)).epsilon(1e-12));
}

TEST_CASE("tolerance areas of a linear field are clipped exactly", "[stats]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(4, 1.0), 0.09, ncv::SamplingScheme::all);
  const auto d = distances_of(samples, [](Vec3 p) { return p[0] + p[1] - 1; });
  // d > 0.4 on the corner triangle with legs 0.6; d < -0.7 on the one with legs 0.3.
  const ErrorStatistics stats = compute_error_statistics(samples, d, Tolerance{-0.7, 0.4});
  REQUIRE(stats.tolerance);
  CHECK(stats.tolerance->excess == Approx(0.18).epsilon(1e-13));
  CHECK(stats.tolerance->gouge == Approx(0.045).epsilon(1e-13));
  CHECK(stats.tolerance->within == Approx(1 - 0.18 - 0.045).epsilon(1e-13));
  CHECK(stats.share(stats.tolerance->excess) == Approx(0.18).epsilon(1e-13));
  CHECK(judge(stats, std::nullopt, stats.tolerance->tolerance) == ncv::Verdict::fail);
}

TEST_CASE("the histogram holds the exact area per bin", "[stats]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(2, 1.0), 0.1, ncv::SamplingScheme::all);
  const auto d = distances_of(samples, [](Vec3 p) { return p[0] + p[1]; });
  const ErrorStatistics stats =
      compute_error_statistics(samples, d, std::nullopt, {.bins = 4, .range = {}});
  const ncv::Histogram& h = stats.histogram;
  REQUIRE(h.bin_count() == 4);
  CHECK(h.range.lo == 0);
  CHECK(h.range.hi == 2);
  CHECK(h.edge(1) == 0.5);
  CHECK(h.area[0] == Approx(1.0 / 8).epsilon(1e-13));
  CHECK(h.area[1] == Approx(3.0 / 8).epsilon(1e-13));
  CHECK(h.area[2] == Approx(3.0 / 8).epsilon(1e-13));
  CHECK(h.area[3] == Approx(1.0 / 8).epsilon(1e-13));
  CHECK(h.below_range == 0);
  CHECK(h.above_range == 0);

  SECTION("a narrower range puts the rest below and above it") {
    const ErrorStatistics narrow = compute_error_statistics(
        samples, d, std::nullopt, {.bins = 2, .range = ncv::ValueRange{0.5, 1.5}});
    CHECK(narrow.histogram.below_range == Approx(1.0 / 8).epsilon(1e-13));
    CHECK(narrow.histogram.area[0] == Approx(3.0 / 8).epsilon(1e-13));
    CHECK(narrow.histogram.area[1] == Approx(3.0 / 8).epsilon(1e-13));
    CHECK(narrow.histogram.above_range == Approx(1.0 / 8).epsilon(1e-13));
    CHECK(narrow.histogram.total_area == Approx(1).epsilon(1e-13));
  }
  SECTION("bad histogram options are usage errors") {
    CHECK_THROWS_AS(compute_error_statistics(samples, d, std::nullopt, {.bins = 0, .range = {}}),
                    ncv::UsageError);
    CHECK_THROWS_AS(compute_error_statistics(samples, d, std::nullopt,
                                             {.bins = 4, .range = ncv::ValueRange{1, 0}}),
                    ncv::UsageError);
  }
}

TEST_CASE("scallop statistics converge to the analytic profile", "[stats]") {
  const double r = 3, stepover = 1;
  // The square spans whole periods, so its mean is the mean over one period; |u| is
  // uniform on [0, s/2] and the profile grows with |u|, so the q-quantile is at |u| = q s/2.
  const auto error_at = [&](double step) {
    const SampleSet samples =
        ncv::sample_mesh(ncv::test::flat_grid(5, 10.0), step, ncv::SamplingScheme::all);
    const auto d = distances_of(samples, [&](Vec3 p) { return scallop(p[0], r, stepover); });
    const ErrorStatistics stats = compute_error_statistics(samples, d, std::nullopt);
    const double exact_median = scallop(0.25 * stepover + stepover / 2, r, stepover);
    const double exact_p95 = scallop(0.95 * stepover / 2 + stepover / 2, r, stepover);
    return std::array{std::abs(stats.mean - scallop_mean(r, stepover)),
                      std::abs(percentile(stats, 50) - exact_median),
                      std::abs(percentile(stats, 95) - exact_p95)};
  };
  const auto coarse = error_at(0.1);
  const auto fine = error_at(0.025);
  const double height = scallop(0, r, stepover);
  CHECK(coarse[0] < 0.02 * height);
  CHECK(fine[0] < 0.003 * height);
  CHECK(fine[0] < coarse[0] / 4);
  CHECK(fine[1] < 0.01 * height);
  CHECK(fine[1] < coarse[1]);
  CHECK(fine[2] < 0.01 * height);
}

TEST_CASE("constant offsets per box face give the exact area-weighted measures", "[stats]") {
  // Faces 2x3 (area 6, two of them), 1x3 (3) and 1x2 (2); total 22.
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::unwelded_box(1, 2, 3), 0.3, ncv::SamplingScheme::all);
  // Every sample lies on one face (the box is unwelded) and its owner is one of that
  // face's two triangles.
  const double offset[6] = {-0.2, 0.1, 0.05, 0.05, 0.3, -0.05};
  std::vector<double> by_face(samples.sample_count());
  for (std::size_t s = 0; s < by_face.size(); ++s) by_face[s] = offset[samples.owner[s] / 2];
  const double areas[6] = {6, 6, 3, 3, 2, 2};
  double integral = 0;
  for (int f = 0; f < 6; ++f) integral += areas[f] * offset[f];
  const ErrorStatistics stats = compute_error_statistics(samples, by_face, Tolerance{-0.1, 0.2});
  CHECK(stats.sampled_area == Approx(22).epsilon(1e-14));
  CHECK(stats.mean == Approx(integral / 22).epsilon(1e-13));
  CHECK(stats.min.value == -0.2);
  CHECK(stats.max.value == 0.3);
  REQUIRE(stats.tolerance);
  CHECK(stats.tolerance->gouge == Approx(6).epsilon(1e-13));
  CHECK(stats.tolerance->excess == Approx(2).epsilon(1e-13));
  CHECK(stats.tolerance->within == Approx(14).epsilon(1e-13));
  // Sorted by value the areas are -0.2:6, -0.05:2, 0.05:6, 0.1:6, 0.3:2.
  CHECK(percentile(stats, 1) == -0.2);
  CHECK(percentile(stats, 5) == -0.2);
  CHECK(percentile(stats, 50) == 0.05);
  CHECK(percentile(stats, 95) == 0.3);
  CHECK(percentile(stats, 99) == 0.3);
}

TEST_CASE("the measures match a plain sub-triangle by sub-triangle recomputation", "[stats]") {
  const SampleSet samples = ncv::sample_mesh(uneven_surface(), 0.03, ncv::SamplingScheme::all);
  std::uint32_t smallest = 1000, largest = 0;
  for (std::uint32_t n : samples.lattice_sizes) {
    smallest = std::min(smallest, n);
    largest = std::max(largest, n);
  }
  REQUIRE(smallest == 2);
  REQUIRE(largest >= 6);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> noise(-0.1, 0.1);
  std::vector<double> d =
      distances_of(samples, [](Vec3 p) { return 0.2 * std::sin(3 * p[0] + p[1]); });
  for (double& v : d) v += noise(random);
  const Tolerance zone{-0.15, 0.1};

  const Reference ref = reference_measures(samples, d, zone);
  const ErrorStatistics stats = compute_error_statistics(samples, d, zone);
  CHECK(stats.sampled_area == Approx(ref.area).epsilon(1e-12));
  CHECK(stats.workpiece_area == Approx(ncv::surface_area(samples.mesh)).epsilon(1e-14));
  CHECK(stats.mean == Approx(ref.integral / ref.area).epsilon(1e-11));
  CHECK(stats.rms == Approx(std::sqrt(ref.squares / ref.area)).epsilon(1e-11));
  const double mean = ref.integral / ref.area;
  CHECK(stats.std_dev == Approx(std::sqrt(ref.squares / ref.area - mean * mean)).epsilon(1e-9));
  REQUIRE(stats.tolerance);
  CHECK(stats.tolerance->excess == Approx(ref.excess).epsilon(1e-11));
  CHECK(stats.tolerance->gouge == Approx(ref.gouge).epsilon(1e-11));
  CHECK(stats.tolerance->within == Approx(ref.area - ref.excess - ref.gouge).epsilon(1e-11));
  double histogram_area = 0;
  for (double a : stats.histogram.area) histogram_area += a;
  CHECK(histogram_area == Approx(ref.area).epsilon(1e-12));
}

TEST_CASE("a histogram bin holds the values above its lower edge up to its upper one", "[stats]") {
  // Atoms (constant patches) of distinct areas on every edge, between edges and at random:
  // each must land in the bin a binary search over the edges gives.
  const ncv::ValueRange range{-0.3, 0.7787481844190582};
  const std::uint32_t bins = 37;
  ncv::Histogram edges_of;
  edges_of.range = range;
  edges_of.area.resize(bins);
  std::vector<double> edges(bins + 1);
  for (std::size_t k = 0; k <= bins; ++k) edges[k] = edges_of.edge(k);
  std::vector<double> values = edges;
  for (std::size_t k = 0; k < bins; ++k) {
    values.push_back(std::nextafter(edges[k], INFINITY));
    values.push_back(std::nextafter(edges[k + 1], -INFINITY));
  }
  std::mt19937_64 random(17);
  std::uniform_real_distribution<double> anywhere(range.lo, range.hi);
  for (int i = 0; i < 2000; ++i) values.push_back(anywhere(random));
  std::vector<double> expected(bins, 0.0);
  std::vector<ncv::LinearPatch> patches;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double area = 1.0 + static_cast<double>(i) / 1024;  // exact sums in any order
    patches.push_back(ncv::make_linear_patch(area, values[i], values[i], values[i]));
    const auto first_not_below = std::lower_bound(edges.begin(), edges.end(), values[i]);
    const auto j = static_cast<std::size_t>(first_not_below - edges.begin());
    expected[j == 0 ? 0 : std::min<std::size_t>(j - 1, bins - 1)] += area;
  }
  const ncv::Histogram h = ncv::area_histogram(patches, range, bins);
  for (std::size_t k = 0; k < bins; ++k) {
    INFO("bin " << k);
    CHECK(h.area[k] == expected[k]);
  }
  CHECK(h.below_range == 0);
  CHECK(h.above_range == 0);
}

TEST_CASE("percentiles invert the exact area distribution", "[stats]") {
  const SampleSet samples = ncv::sample_mesh(uneven_surface(), 0.05, ncv::SamplingScheme::all);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> noise(-1, 1);
  std::vector<double> d(samples.sample_count());
  for (double& v : d) v = noise(random);
  const ErrorStatistics stats = compute_error_statistics(samples, d, std::nullopt);
  const std::vector<ncv::LinearPatch> patches = all_patches(samples, d);
  check_percentiles_invert(stats, patches);
}

TEST_CASE("quantiles of atoms and ramps", "[stats]") {
  // An atom of area 1 at 0 and a ramp of area 1 rising linearly from 1 to 3: the first
  // half of the area sits at 0, the ramp's lower half lies in [1, 1 + sqrt(2)].
  const std::vector<ncv::LinearPatch> patches = {ncv::make_linear_patch(1, 0, 0, 0),
                                                 ncv::make_linear_patch(1, 1, 3, 3)};
  const std::vector<double> values = {3, 0, 1, 0, 3, 0};  // the corner values, any order
  const std::vector<double> fractions = {0, 0.25, 0.5, 0.5 + 1e-12, 0.75, 1};
  const std::vector<double> q = ncv::area_quantiles(ncv::StoredPatches(patches), values, fractions);
  CHECK(q[0] == 0);
  CHECK(q[1] == 0);
  CHECK(q[2] == 0);
  // Just past the atom: the ramp's first 2e-12 of area ends at 1 + sqrt(8e-12).
  CHECK(q[3] == Approx(1 + std::sqrt(8e-12)).margin(1e-9));
  // The ramp patch has F(t) = (t - 1)^2 / 4 on [1, 3]: half its area below 1 + sqrt(2).
  CHECK(q[4] == Approx(1 + std::sqrt(2.0)).epsilon(1e-14));
  CHECK(q[5] == 3);
  const std::vector<ncv::LinearPatch> no_area = {ncv::make_linear_patch(0, 0, 1, 2)};
  CHECK(std::isnan(ncv::area_quantiles(ncv::StoredPatches(no_area), std::vector<double>{0, 1, 2},
                                       fractions)[2]));
}

TEST_CASE("the verdict passes exactly up to the tolerance limits", "[stats]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(2, 1.0), 0.2, ncv::SamplingScheme::all);
  const auto d = distances_of(samples, [](Vec3 p) { return 0.25 * p[0] - 0.125; });
  // Certified bounds equal to the sampled extremes (the field is linear): the verdict is the
  // samples' own.
  const auto verdict = [&](Tolerance zone) {
    const ErrorStatistics s = compute_error_statistics(samples, d, zone);
    ncv::Certificate c;
    c.max = {s.max.value, Vec3(0, 0, 0), s.max.value, Vec3(0, 0, 0)};
    c.min = {s.min.value, Vec3(0, 0, 0), s.min.value, Vec3(0, 0, 0)};
    return judge(s, c, zone) == ncv::Verdict::pass;
  };
  CHECK(verdict({-0.125, 0.125}));
  CHECK(verdict({-0.5, 0.5}));
  CHECK_FALSE(verdict({-0.125, std::nextafter(0.125, 0.0)}));
  CHECK_FALSE(verdict({std::nextafter(-0.125, 0.0), 0.125}));
  const ErrorStatistics at_limits = compute_error_statistics(samples, d, Tolerance{-0.125, 0.125});
  CHECK(at_limits.tolerance->excess == 0);
  CHECK(at_limits.tolerance->gouge == 0);
  CHECK(at_limits.tolerance->within == Approx(1).epsilon(1e-14));
  CHECK_FALSE(compute_error_statistics(samples, d, std::nullopt).tolerance);
}

TEST_CASE("triangle counts follow the sampling scheme", "[stats]") {
  // The narrow cells near x = 0 round below 2 at this step, the wide ones do not.
  const ncv::Mesh mesh = uneven_surface();
  const double step = 0.12;
  std::uint64_t small = 0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    small += ncv::lattice_size(ncv::triangle_area(mesh, t), step) < 2;
  }
  REQUIRE(small > 0);
  REQUIRE(small < mesh.triangle_count());
  for (const auto scheme : {ncv::SamplingScheme::all, ncv::SamplingScheme::paper_ii}) {
    const SampleSet samples = ncv::sample_mesh(mesh, step, scheme);
    const auto d = distances_of(samples, [](Vec3 p) { return p[2]; });
    const ErrorStatistics stats = compute_error_statistics(samples, d, std::nullopt);
    CHECK(stats.samples == samples.sample_count());
    CHECK(stats.triangles == mesh.triangle_count());
    const bool all = scheme == ncv::SamplingScheme::all;
    CHECK(stats.triangles_vertex_only == (all ? small : 0));
    CHECK(stats.triangles_unsampled == (all ? 0 : small));
    if (all) {
      CHECK(stats.sampled_area == Approx(stats.workpiece_area).epsilon(1e-13));
    } else {
      CHECK(stats.sampled_area < stats.workpiece_area);
    }
  }
}

TEST_CASE("statistics do not depend on the thread count", "[stats]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(40, 1.0), 0.0025, ncv::SamplingScheme::all);
  REQUIRE(samples.sample_count() > 100000);
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  std::vector<double> d = distances_of(samples, [](Vec3 p) { return std::sin(9 * p[0]) * p[1]; });
  for (double& v : d) v += noise(random);
  const auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return compute_error_statistics(samples, d, Tolerance{-0.5, 0.4});
  };
  const ErrorStatistics one = run(1), many = run(4);
  CHECK(one.mean == many.mean);
  CHECK(one.rms == many.rms);
  CHECK(one.std_dev == many.std_dev);
  CHECK(one.sampled_area == many.sampled_area);
  CHECK(one.tolerance->within == many.tolerance->within);
  CHECK(one.tolerance->excess == many.tolerance->excess);
  CHECK(one.histogram.area == many.histogram.area);
  for (std::size_t k = 0; k < one.percentiles.size(); ++k) {
    CHECK(one.percentiles[k].value == many.percentiles[k].value);
  }
}

TEST_CASE("percentiles of a field of many patch blocks invert the exact distribution", "[stats]") {
  // Several blocks of 65536 patches: the distribution at the split points is reduced over
  // blocks in parallel.
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(40, 1.0), 0.0025, ncv::SamplingScheme::all);
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  std::vector<double> d = distances_of(samples, [](Vec3 p) { return std::sin(9 * p[0]) * p[1]; });
  for (double& v : d) v += noise(random);
  const std::vector<ncv::LinearPatch> patches = all_patches(samples, d);
  REQUIRE(patches.size() > 3 * 65536);
  const ErrorStatistics stats = compute_error_statistics(samples, d, std::nullopt);
  check_percentiles_invert(stats, patches);
}

TEST_CASE("distances that do not fit the samples are input errors", "[stats]") {
  const SampleSet samples =
      ncv::sample_mesh(ncv::test::flat_grid(1, 1.0), 1, ncv::SamplingScheme::all);
  std::vector<double> d(samples.sample_count(), 0.0);
  CHECK_NOTHROW(compute_error_statistics(samples, d, std::nullopt));
  CHECK_THROWS_AS(compute_error_statistics(samples, std::span(d).first(d.size() - 1), std::nullopt),
                  ncv::InputError);
  d[1] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(compute_error_statistics(samples, d, std::nullopt),
                    Catch::Contains("sample 1"));
  const SampleSet nothing =
      ncv::sample_mesh(ncv::test::flat_grid(1, 1.0), 10, ncv::SamplingScheme::paper_ii);
  CHECK_THROWS_AS(compute_error_statistics(nothing, std::vector<double>{}, std::nullopt),
                  ncv::InputError);
}

TEST_CASE("the mean divides by the whole workpiece area, also under scheme II", "[stats]") {
  // A 10 x 10 square (sampled) and a small far triangle of area 0.5 that scheme II skips.
  ncv::Mesh mesh{
      {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 0}, {50, 50, 50}, {51, 50, 50}, {50, 51, 50}},
      {{0, 1, 2}, {3, 2, 1}, {4, 5, 6}}};
  const ncv::SampleSet set = ncv::sample_mesh(mesh, 2.0, ncv::SamplingScheme::paper_ii);
  REQUIRE(set.lattice_sizes[2] == 0);
  const std::vector<double> d(set.sample_count(), 1.0);
  const ncv::ErrorStatistics stats = ncv::compute_error_statistics(set, d, std::nullopt);
  CHECK(stats.workpiece_area == Approx(100.5));
  CHECK(stats.sampled_area == Approx(100.0));
  CHECK(stats.mean == Approx(100.0 / 100.5));  // paper eq. 7: (1/|S1|) ∫ d dS
  CHECK(stats.rms == Approx(1.0));             // over the sampled surface
  CHECK(stats.std_dev == Approx(0.0).margin(1e-12));
}
