// Verification in process: two TriMeshes through run's steps, results with the known answer
// of a lowered box top, and the coloured workpiece.
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
  return options;
}

}  // namespace

TEST_CASE("a box whose top is 0.2 low fails a ±0.1 zone, gouged by 0.2", "[mesh_verification]") {
  const ncv::TriMesh nominal = ncv::tri_mesh(fx::box({0, 0, 0}, {10, 6, 4}));
  const ncv::TriMesh workpiece = ncv::tri_mesh(fx::box({0, 0, 0}, {10, 6, 3.8}));
  const ncv::Verification result = ncv::verify(workpiece, nominal, coarse_options({-0.1, 0.1}),
                                               {"parts/lowered.stl", "parts/box.stl"});
  const ncv::ErrorStatistics& s = result.report.statistics;
  // The sides and the bottom lie on the nominal (up to the closest point's rounding); the
  // top's samples farther than 0.2 from its rim are nearest to the nominal's top.
  CHECK(s.max.value == Approx(0).margin(1e-12));
  CHECK(s.min.value == -(4 - 3.8));
  REQUIRE(s.tolerance);
  CHECK_FALSE(s.tolerance->pass);
  CHECK(ncv::verdict_status(result.report) == 1);
  REQUIRE(result.report.regions.size() == 1);
  CHECK(result.report.regions[0].kind == ncv::RegionKind::gouge);
  CHECK(result.report.part == "lowered");
  CHECK(result.forward->samples.source == "parts/lowered.stl");
  CHECK(result.forward->reference.source == "parts/box.stl");
  CHECK(result.forward->samples.step == 0.5);
  CHECK(result.report.distances == result.forward.get());
}

TEST_CASE("the result stays whole when moved", "[mesh_verification]") {
  const ncv::TriMesh nominal = ncv::tri_mesh(fx::box({0, 0, 0}, {10, 6, 4}));
  ncv::Verification first = ncv::verify(nominal, nominal, coarse_options({-0.1, 0.1}));
  const ncv::DistanceSet* distances = first.forward.get();
  const ncv::Verification moved = std::move(first);
  CHECK(moved.report.distances == distances);
  CHECK(moved.report.statistics.max_abs.value == Approx(0).margin(1e-12));
  CHECK(ncv::verdict_status(moved.report) == 0);
}

TEST_CASE("the coloured workpiece holds each vertex's error and colour", "[mesh_verification]") {
  const ncv::TriMesh nominal = ncv::tri_mesh(fx::box({0, 0, 0}, {10, 6, 4}));
  const ncv::TriMesh workpiece = ncv::tri_mesh(fx::box({0, 0, 0}, {10, 6, 3.8}));
  const ncv::Verification result = ncv::verify(workpiece, nominal, coarse_options({-0.1, 0.1}));
  ncv::TriMesh colored = ncv::colored_workpiece(result);
  REQUIRE(colored.n_vertices() == workpiece.n_vertices());
  REQUIRE(colored.n_faces() == workpiece.n_faces());
  const ncv::SampleSet& samples = result.forward->samples;
  const auto error = OpenMesh::VProp<double>(colored, ncv::kSignedErrorProperty);
  const ncv::ColoredSurface painted = ncv::colorize(*result.forward, result.colorize);
  CHECK(painted.map.kind == ncv::ColorMapKind::tolerance);
  for (const auto vertex : colored.vertices()) {
    const double d = result.forward->field.distance[samples.vertex_sample[vertex.idx()]];
    CHECK(error[vertex] == d);
    const ncv::Rgb rgb = painted.map.rgb(d);
    CHECK(colored.color(vertex) == ncv::TriMesh::Color(rgb[0], rgb[1], rgb[2]));
    CHECK(colored.point(vertex) == workpiece.point(vertex));
  }

  ncv::VerifyOptions lattice = coarse_options({-0.1, 0.1});
  lattice.colorize.lattice = true;
  const ncv::TriMesh every_sample =
      ncv::colored_workpiece(ncv::verify(workpiece, nominal, lattice));
  CHECK(every_sample.n_vertices() == samples.sample_count());
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
