// Certified bounds against the truth: dense exact sampling of the workpiece never falls
// outside the certified interval, a box whose lowered top the lattice misses is caught, and
// the certificate does not depend on the thread count.
#include <catch2/catch.hpp>

#include <tbb/global_control.h>

#include <random>

#include "certify/certify_surface.hpp"
#include "nominal_fixtures.hpp"
#include "search/indexed_reference.hpp"
#include "stats_fixtures.hpp"

namespace ncv {
namespace {

struct Certified {
  Certificate certificate;
  double sampled_max = 0, sampled_min = 0;
};

Certified certify(const Mesh& workpiece, const IndexedReference& nominal, double step,
                  const CertifyOptions& options = {}) {
  const SampleSet samples = sample_mesh(workpiece, step, SamplingScheme::all);
  const SearchIndex index(nominal);
  const SideRule side(*nominal.surface, SignMethod::pseudonormal);
  const DistanceField raw =
      compute_signed_distances(index, samples.positions, {}, SignMethod::pseudonormal);
  Certified c{certify_surface(samples, raw, index, side, options),
              *std::max_element(raw.distance.begin(), raw.distance.end()),
              *std::min_element(raw.distance.begin(), raw.distance.end())};
  return c;
}

// The exact signed error at `per_triangle` random points of every workpiece triangle, by
// brute force over the nominal: its largest and smallest value.
std::pair<double, double> dense_extremes(const Mesh& workpiece, const IndexedReference& nominal,
                                         int per_triangle) {
  std::mt19937_64 rng(5);
  std::vector<Vec3> points;
  for (std::size_t t = 0; t < workpiece.triangle_count(); ++t) {
    for (int k = 0; k < per_triangle; ++k)
      points.push_back(fixtures::random_point_on(rng, workpiece, t));
    for (int k = 0; k < 3; ++k) points.push_back(workpiece.corner(t, k));
  }
  const DistanceField d =
      compute_signed_distances(*nominal.surface, points, {}, SignMethod::pseudonormal);
  return {*std::max_element(d.distance.begin(), d.distance.end()),
          *std::min_element(d.distance.begin(), d.distance.end())};
}

// The certified interval holds the exact error at `per_triangle` random points of every
// triangle of the sampled mesh and at its corners.
void check_holds_dense_truth(const Certificate& c, const Mesh& sampled,
                             const IndexedReference& reference, int per_triangle) {
  const auto [true_max, true_min] = dense_extremes(sampled, reference, per_triangle);
  CHECK(c.max.bound >= true_max);
  CHECK(c.min.bound <= true_min);
}

void check_contains_truth(const Mesh& workpiece, const IndexedReference& nominal, double step) {
  const Certified c = certify(workpiece, nominal, step, CertifyOptions{0.01, 0});
  check_holds_dense_truth(c.certificate, workpiece, nominal, 400);
  CHECK(c.certificate.max.measured >= c.sampled_max);
  CHECK(c.certificate.min.measured <= c.sampled_min);
  CHECK(c.certificate.sign_proven);
  if (c.certificate.unresolved == 0) {
    CHECK(c.certificate.max.width() <= 0.01);
    CHECK(c.certificate.min.width() <= 0.01);
  }
}

}  // namespace

TEST_CASE("a box whose top is 0.2 low is caught between samples at a coarse step", "[certify]") {
  const IndexedReference nominal =
      index_reference(fixtures::box({-50, -50, 0}, {50, 50, 30}), "box");
  const Mesh lowered = fixtures::box({-50, -50, 0}, {50, 50, 29.8});
  const Certified c = certify(lowered, nominal, 40.0);
  // The samples are the corners, on the nominal's walls: they read 0.
  CHECK(c.sampled_min == 0);
  CHECK(c.certificate.min.bound <= -0.2);
  CHECK(c.certificate.min.measured == Approx(-0.2).margin(1e-9));
  CHECK(c.certificate.added_points > 0);
}

TEST_CASE("a box offset outward is bounded to the width asked", "[certify]") {
  const IndexedReference nominal = index_reference(fixtures::box({0, 0, 0}, {10, 10, 10}), "box");
  const Mesh raised = fixtures::box({-0.1, -0.1, -0.1}, {10.1, 10.1, 10.1});
  const Certified c = certify(raised, nominal, 1.0, CertifyOptions{0.001, 0});
  // The corners are sqrt(3) * 0.1 away, the faces 0.1: every point is between.
  CHECK(c.certificate.max.bound >= std::sqrt(3.0) * 0.1);
  CHECK(c.certificate.max.width() <= 0.001);
  CHECK(c.certificate.min.bound <= 0.1);
  CHECK(c.certificate.min.bound >= 0.1 - 0.001);
  CHECK(c.certificate.unresolved == 0);
}

TEST_CASE("dense exact sampling never leaves the certified interval", "[certify]") {
  SECTION("a coarse torus against a finer, fatter one") {
    const IndexedReference nominal = index_reference(fixtures::torus(10, 3.2, 48, 24), "torus");
    check_contains_truth(fixtures::torus(10, 3, 20, 10), nominal, 1.5);
  }
  SECTION("a pocketed block against itself moved by less than the step") {
    const Mesh block = fixtures::pocketed_block().mesh(5);
    const IndexedReference nominal = index_reference(block, "block");
    check_contains_truth(fixtures::translated(block, {0.13, -0.07, 0.21}), nominal, 2.0);
  }
  SECTION("a torus crossing a box") {
    const IndexedReference nominal = index_reference(fixtures::box({-9, -9, -2}, {9, 9, 2}), "box");
    check_contains_truth(fixtures::torus(8, 2.5, 24, 12), nominal, 1.0);
  }
}

TEST_CASE("a face machined exactly to the nominal beside an uncut slot is certified to the width",
          "[certify]") {
  // Six voxels by four by three with a slot one wide and one deep across the top: where the
  // uncut top meets the slot's rim, the workpiece touches the nominal from one side only.
  fixtures::VoxelSolid slotted, uncut;
  slotted.fill(0, 0, 0, 6, 4, 3);
  slotted.carve(2, 0, 2, 3, 4, 3);
  uncut.fill(0, 0, 0, 6, 4, 3);
  const double width = 0.001;
  SECTION("from the workpiece: the top over the slot is half its width away") {
    const IndexedReference nominal = index_reference(slotted.mesh(1.0), "slotted");
    const Mesh workpiece = uncut.mesh(1.0);
    const Certified c = certify(workpiece, nominal, 0.3, CertifyOptions{width, 0});
    CHECK(c.certificate.unresolved == 0);
    CHECK(c.certificate.max.measured == Approx(0.5).margin(1e-12));
    CHECK(c.certificate.max.width() <= width);
    CHECK(c.certificate.min.bound >= -width);
    check_holds_dense_truth(c.certificate, workpiece, nominal, 400);
  }
  SECTION("from the nominal: its slot lies inside the uncut block, down to its depth") {
    const IndexedReference workpiece = index_reference(uncut.mesh(1.0), "uncut");
    const Mesh nominal = slotted.mesh(1.0);
    const Certified c = certify(nominal, workpiece, 0.3, CertifyOptions{width, 0});
    CHECK(c.certificate.unresolved == 0);
    CHECK(c.certificate.min.measured == Approx(-1.0).margin(1e-12));
    CHECK(c.certificate.min.width() <= width);
    CHECK(c.certificate.max.bound <= width);
    check_holds_dense_truth(c.certificate, nominal, workpiece, 400);
  }
}

TEST_CASE("a zero-area triangle along a contact line is certified to the width", "[certify]") {
  // The block's own surface (the error is 0 on it) with a sliver of zero area along a
  // vertical edge and 2 above the block, as a CAD export leaves them beside a rib the block
  // lacks: a patch with no normal, touching the block, whose side only a prism across its line
  // proves; splitting it would need patches as short as the width.
  const Mesh block = fixtures::box({0, 0, 0}, {6, 4, 3});
  const IndexedReference reference = index_reference(block, "block");
  Mesh sampled = block;
  const auto first = static_cast<std::uint32_t>(sampled.vertices.size());
  for (const double z : {0.0, 3.0, 5.0}) sampled.vertices.push_back(Vec3(0, 0, z));
  sampled.triangles.push_back({first, first + 1, first + 2});
  const double width = 0.001;
  const Certified c = certify(sampled, reference, 0.3, CertifyOptions{width, 0});
  CHECK(c.certificate.unresolved == 0);
  CHECK(c.certificate.added_points < 100);
  CHECK(c.certificate.max.measured == Approx(2.0).margin(1e-12));
  CHECK(c.certificate.max.width() <= width);
  CHECK(c.certificate.min.bound >= -width);
  check_holds_dense_truth(c.certificate, sampled, reference, 100);
}

TEST_CASE("a coarse face over a finely facetted scallop surface is certified to the width",
          "[certify]") {
  // Twenty scallops 1 wide, cut by a ball of radius 3 (cusps 0.042 high), each arc in 8
  // strips across the block: the nominal's two top triangles hold hundreds of patches each
  // over reference strips much finer than the patch (bounded per triangle: TriangleCover).
  const Mesh scalloped = fixtures::scalloped_block(20, 6, 5, 20, 3.0, 8);
  const Mesh flat = fixtures::box({0, 0, 0}, {20, 6, 5});
  const double width = 0.001;
  SECTION("from the nominal: its top lies under the scallops, touching their troughs") {
    const IndexedReference workpiece = index_reference(scalloped, "scallops");
    const Certified c = certify(flat, workpiece, 0.7, CertifyOptions{width, 0});
    CHECK(c.certificate.unresolved == 0);
    CHECK(c.certificate.min.width() <= width);
    CHECK(c.certificate.max.width() <= width);
    check_holds_dense_truth(c.certificate, flat, workpiece, 2000);
    // Settled per triangle: few points added, few patches split.
    CAPTURE(c.certificate.added_points, c.certificate.refined_patches, c.certificate.patches);
    CHECK(c.certificate.refined_patches * 100 < c.certificate.patches);
  }
  SECTION("from the workpiece") {
    const IndexedReference nominal = index_reference(flat, "flat");
    const Certified c = certify(scalloped, nominal, 0.3, CertifyOptions{width, 0});
    CHECK(c.certificate.unresolved == 0);
    check_holds_dense_truth(c.certificate, scalloped, nominal, 400);
  }
}

TEST_CASE("walls reaching above a box's edge are bounded across its faces' diagonals",
          "[certify]") {
  // A scalloped block over a box its troughs touch: the workpiece's end walls rise to the
  // cusps above the nominal's top edge, and their patches (a coarse step) cross the
  // diagonals of the nominal's end faces (two triangles each), where no single triangle is
  // near all corners; the two halves together are (flat_pair_upper_abs).
  const Mesh scalloped = fixtures::scalloped_block(20, 6, 5, 20, 3.0, 8);
  const IndexedReference nominal = index_reference(fixtures::box({0, 0, 0}, {20, 6, 5}), "box");
  const Certified c = certify(scalloped, nominal, 3.0, CertifyOptions{0.001, 0});
  CAPTURE(c.certificate.added_points, c.certificate.refined_patches);
  CHECK(c.certificate.unresolved == 0);
  CHECK(c.certificate.max.width() <= 0.001);
  CHECK(c.certificate.min.bound >= -0.001);
  CHECK(c.certificate.refined_patches <= 10);
  check_holds_dense_truth(c.certificate, scalloped, nominal, 400);
}

TEST_CASE("the certificate does not depend on the thread count", "[certify]") {
  const IndexedReference nominal = index_reference(fixtures::torus(10, 3.2, 48, 24), "torus");
  const Mesh workpiece = fixtures::torus(10, 3, 30, 14);
  const auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return certify(workpiece, nominal, 0.7, CertifyOptions{0.0005, 0}).certificate;
  };
  const Certificate one = run(1), two = run(2);
  CHECK(one.max.bound == two.max.bound);
  CHECK(one.min.bound == two.min.bound);
  CHECK(one.max.measured == two.max.measured);
  CHECK(one.min.measured == two.min.measured);
  CHECK(one.max.bound_at == two.max.bound_at);
  CHECK(one.added_points == two.added_points);
  CHECK(one.unresolved == two.unresolved);
}

TEST_CASE("refinement stops at its cap and says what is unresolved", "[certify]") {
  const IndexedReference nominal =
      index_reference(fixtures::box({-50, -50, 0}, {50, 50, 30}), "box");
  const Mesh lowered = fixtures::box({-50, -50, 0}, {50, 50, 29.8});
  const Certified c = certify(lowered, nominal, 40.0, CertifyOptions{1e-6, 300});
  CHECK(c.certificate.added_points <= 300);
  CHECK(c.certificate.unresolved > 0);
  CHECK(c.certificate.min.bound <= -0.2);  // still sound
}

}  // namespace ncv

namespace ncv {

TEST_CASE("a patch over a finely tessellated flat face is bounded by its height above it",
          "[certify]") {
  // The reference: a 10 x 10 square in z = 0 of 800 small triangles (open, so only |d| is
  // bounded); the sampled surface: one large triangle 0.01 above it, sampled at its corners.
  const IndexedReference nominal = index_reference(test::flat_grid(20, 10), "grid");
  Mesh above{{{1, 1, 0.01}, {9, 1.5, 0.01}, {2, 8.5, 0.01}}, {{0, 1, 2}}};
  const Certified c = certify(above, nominal, 100.0, CertifyOptions{0.001, 0});
  CHECK(c.certificate.max.bound <= 0.01 + 0.001);
  CHECK(c.certificate.min.bound >= -0.01 - 0.001);
  // Over an open surface the side is not proven, so only |d| is bounded: within the width.
  CHECK(c.certificate.max.width() <= 0.001);
}

}  // namespace ncv
