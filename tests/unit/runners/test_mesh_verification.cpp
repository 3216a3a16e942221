// Verification in process: two TriMeshes through run's steps in both directions, results
// with the known answers of a lowered box top, and the coloured workpiece and nominal.
#include <catch2/catch.hpp>

#include <OpenMesh/Core/Utils/PropertyManager.hh>

#include "nominal_fixtures.hpp"
#include "render/colored_tri_mesh.hpp"
#include "runners/mesh_verification.hpp"
#include "util/error.hpp"

namespace {

namespace fx = ncv::fixtures;

ncv::VerifyOptions coarse_options(ncv::Tolerance tolerance) {
  ncv::VerifyOptions options;
  options.sampling.step = ncv::SamplingStep{0.5, false};
  options.report.tolerance = tolerance;
  options.colorize.coarse = true;  // the coloured meshes keep the input's vertices
  return options;
}

// Each vertex of the coloured mesh carries its sample's error and the colour the map gives
// it, at its own position.
void check_colored(ncv::TriMesh& colored, const ncv::TriMesh& original,
                   const ncv::DistanceSet& distances, const ncv::ColorizeOptions& options) {
  REQUIRE(colored.n_vertices() == original.n_vertices());
  REQUIRE(colored.n_faces() == original.n_faces());
  const auto error = OpenMesh::VProp<double>(colored, ncv::kSignedErrorProperty);
  const ncv::ColoredSurface painted = ncv::colorize(distances, options);
  for (const auto vertex : colored.vertices()) {
    const double d = distances.field.distance[distances.samples.vertex_sample[vertex.idx()]];
    CHECK(error[vertex] == d);
    const ncv::Rgb rgb = painted.map.rgb(d);
    CHECK(colored.color(vertex) == ncv::TriMesh::Color(rgb[0], rgb[1], rgb[2]));
    CHECK(colored.point(vertex) == original.point(vertex));
  }
}

}  // namespace

TEST_CASE("a box whose top is 0.2 low fails a ±0.1 zone, gouged by 0.2 both ways",
          "[mesh_verification]") {
  const ncv::TriMesh nominal = ncv::tri_mesh(fx::box({0, 0, 0}, {10, 6, 4}));
  const ncv::TriMesh workpiece = ncv::tri_mesh(fx::box({0, 0, 0}, {10, 6, 3.8}));
  const ncv::Verification result = ncv::verify(workpiece, nominal, coarse_options({-0.1, 0.1}),
                                               {"parts/lowered.stl", "parts/box.stl"});
  REQUIRE(result.reverse);
  REQUIRE(result.report.reverse);
  // Forward, the sides and the bottom lie on the nominal (up to the closest point's
  // rounding); the top's samples farther than 0.2 from its rim are nearest to the nominal's
  // top. Reverse, the nominal's top lies 0.2 outside the workpiece: a gouge too.
  for (const ncv::PartReport* direction : {&result.report.main, &*result.report.reverse}) {
    const ncv::ErrorStatistics& s = direction->statistics;
    CHECK(s.max.value == Approx(0).margin(1e-12));
    CHECK(s.min.value == -(4 - 3.8));
    REQUIRE(s.tolerance);
    CHECK(direction->verdict() == ncv::Verdict::fail);
    REQUIRE(direction->regions.size() == 1);
    CHECK(direction->regions[0].kind == ncv::RegionKind::gouge);
  }
  CHECK(ncv::verdict_status(result.report) == 1);
  CHECK(result.report.main.part == "lowered");
  CHECK(result.forward->samples.source == "parts/lowered.stl");
  CHECK(result.forward->reference.source == "parts/box.stl");
  CHECK(result.reverse->samples.source == "parts/box.stl");
  CHECK(result.reverse->direction == ncv::Direction::reverse);
  CHECK(result.forward->samples.step == 0.5);
  CHECK(result.reverse->samples.step == 0.5);
  CHECK(result.report.main.distances == result.forward.get());
  CHECK(result.report.reverse->distances == result.reverse.get());
}

TEST_CASE("a slot the workpiece lacks fails only from the nominal's side", "[mesh_verification]") {
  // The nominal is an 8-cube with a slot 1 wide and 3 deep across its top; the workpiece is
  // the uncut cube. Forward, the workpiece's top over the slot reads at most half the slot's
  // width; reverse, the slot's floor reads its depth as material left. A step of 0.3 puts
  // three lattice points on each unit edge (docs/METHOD.md "Sampling"), so the slot's middle
  // is sampled.
  fx::VoxelSolid slotted;
  slotted.fill(0, 0, 0, 8, 8, 8);
  slotted.carve(4, 0, 5, 5, 8, 8);
  fx::VoxelSolid cube;
  cube.fill(0, 0, 0, 8, 8, 8);
  const ncv::TriMesh nominal = ncv::tri_mesh(slotted.mesh(1.0));
  const ncv::TriMesh workpiece = ncv::tri_mesh(cube.mesh(1.0));
  ncv::VerifyOptions options = coarse_options({-0.6, 0.6});
  options.sampling.step = ncv::SamplingStep{0.3, false};
  const ncv::Verification two_sided = ncv::verify(workpiece, nominal, options);
  CHECK(two_sided.report.main.statistics.max.value == 0.5);
  CHECK_FALSE(two_sided.report.main.fails());
  CHECK(two_sided.report.reverse->statistics.max.value == 3);
  CHECK(two_sided.report.fails());

  options.two_sided = false;
  const ncv::Verification one_sided = ncv::verify(workpiece, nominal, options);
  CHECK_FALSE(one_sided.reverse);
  CHECK_FALSE(one_sided.report.reverse);
  CHECK(ncv::verdict_status(one_sided.report) == 0);
  CHECK_THROWS_AS(ncv::colored_nominal(one_sided), ncv::UsageError);
}

TEST_CASE("the result stays whole when moved", "[mesh_verification]") {
  const ncv::TriMesh nominal = ncv::tri_mesh(fx::box({0, 0, 0}, {10, 6, 4}));
  ncv::Verification first = ncv::verify(nominal, nominal, coarse_options({-0.1, 0.1}));
  const ncv::DistanceSet* forward = first.forward.get();
  const ncv::DistanceSet* reverse = first.reverse.get();
  const ncv::Verification moved = std::move(first);
  CHECK(moved.report.main.distances == forward);
  CHECK(moved.report.reverse->distances == reverse);
  CHECK(moved.report.main.statistics.max_abs.value == Approx(0).margin(1e-12));
  CHECK(ncv::verdict_status(moved.report) == 0);
}

TEST_CASE("the coloured workpiece and nominal hold each vertex's error and colour",
          "[mesh_verification]") {
  const ncv::TriMesh nominal = ncv::tri_mesh(fx::box({0, 0, 0}, {10, 6, 4}));
  const ncv::TriMesh workpiece = ncv::tri_mesh(fx::box({0, 0, 0}, {10, 6, 3.8}));
  const ncv::Verification result = ncv::verify(workpiece, nominal, coarse_options({-0.1, 0.1}));
  CHECK(result.colorize.tolerance == ncv::Tolerance{-0.1, 0.1});
  ncv::TriMesh colored_workpiece = ncv::colored_workpiece(result);
  check_colored(colored_workpiece, workpiece, *result.forward, result.colorize);
  ncv::TriMesh colored_nominal = ncv::colored_nominal(result);
  check_colored(colored_nominal, nominal, *result.reverse, result.colorize);

  ncv::VerifyOptions lattice = coarse_options({-0.1, 0.1});
  lattice.colorize.coarse = false;
  const ncv::Verification every_sample = ncv::verify(workpiece, nominal, lattice);
  CHECK(ncv::colored_workpiece(every_sample).n_vertices() ==
        every_sample.forward->samples.sample_count());
}

TEST_CASE("what verify refuses is named", "[mesh_verification]") {
  const ncv::TriMesh nominal = ncv::tri_mesh(fx::box({0, 0, 0}, {1, 1, 1}));
  const ncv::TriMesh far = ncv::tri_mesh(fx::box({100, 0, 0}, {101, 1, 1}));
  CHECK_THROWS_WITH(ncv::verify(far, nominal, {}, {"far.stl", "nominal.stl"}),
                    Catch::StartsWith("far.stl: the workpiece lies"));
  CHECK_THROWS_WITH(ncv::verify(ncv::TriMesh{}, nominal), "workpiece: the mesh has no triangles");
  ncv::VerifyOptions tolerance_map_without_zone;
  tolerance_map_without_zone.colorize.map = ncv::ColorMapKind::tolerance;
  const ncv::Verification no_zone = ncv::verify(nominal, nominal, tolerance_map_without_zone);
  CHECK_THROWS_AS(ncv::colored_workpiece(no_zone), ncv::UsageError);
}
