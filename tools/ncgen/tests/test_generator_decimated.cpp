// The second family: a fine RTIN decimated by OpenMesh, and the parts meshed that way.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ncgen/decimated_parts.hpp"
#include "ncgen/decimation.hpp"
#include "ncgen/height_solid.hpp"
#include "ncgen/nominal_part.hpp"
#include "ncgen/part_size.hpp"
#include "ncgen/rtin.hpp"
#include "ncgen/workpiece.hpp"
#include "test_generator_checks.hpp"
#include "test_generator_distance.hpp"

using namespace ncv::gen;
using ncv::gen::test::check_solid;
using ncv::gen::test::is_sound_solid;

namespace {

struct DecimatedStage {
  MillingStage stage;
  MillingSimulation simulation;
  Workpiece rtin;  // the first family's workpiece of the same Z-map and size
  DecimatedSolid decimated;
};

// Milling and meshing every stage at the small size takes a few seconds: once for all tests.
const std::vector<DecimatedStage>& decimated_stages() {
  static const std::vector<DecimatedStage> stages = [] {
    std::vector<DecimatedStage> made;
    mill_part(make_mould_core(1), small_size, mould_core_stages(),
              [&](const MillingStage& stage, const MillingSimulation& simulation) {
                const std::size_t triangles = workpiece_triangles(stage, small_size);
                made.push_back({stage, simulation, workpiece_mesh(simulation, triangles),
                                decimated_workpiece_mesh(simulation, triangles)});
              });
    return made;
  }();
  return stages;
}

// The top alone, as a mesh: each grid sample at its height.
ncv::Mesh top_mesh(const Grid& grid, const std::vector<float>& heights,
                   const std::vector<GridTriangle>& triangles) {
  ncv::Mesh mesh;
  const auto row = static_cast<std::uint32_t>(grid.samples_x());
  for (std::uint32_t s = 0; s < grid.sample_count(); ++s) {
    mesh.vertices.push_back(ncv::Vec3(grid.x(static_cast<int>(s % row)),
                                      grid.y(static_cast<int>(s / row)), heights[s]));
  }
  for (const GridTriangle& t : triangles) mesh.triangles.push_back({t[0], t[1], t[2]});
  return mesh;
}

// The grid samples the triangles use, as points at their heights.
std::vector<ncv::Vec3> used_samples(const Grid& grid, const std::vector<float>& heights,
                                    const std::vector<GridTriangle>& triangles) {
  std::vector<bool> used(grid.sample_count(), false);
  for (const GridTriangle& t : triangles) {
    for (const std::uint32_t s : t) used[s] = true;
  }
  std::vector<ncv::Vec3> points;
  const auto row = static_cast<std::uint32_t>(grid.samples_x());
  for (std::uint32_t s = 0; s < grid.sample_count(); ++s) {
    if (used[s]) {
      points.push_back(ncv::Vec3(grid.x(static_cast<int>(s % row)),
                                 grid.y(static_cast<int>(s / row)), heights[s]));
    }
  }
  return points;
}

// A triangle's area seen from +z, positive when counter-clockwise.
double projected_area(const ncv::Mesh& mesh, std::size_t t) {
  return ncv::area_vector(mesh, t)[2] / 2;
}

}  // namespace

TEST_CASE("decimated workpieces are closed outward manifolds of the size's triangle count",
          "[generator]") {
  for (const DecimatedStage& s : decimated_stages()) {
    INFO(s.stage.name);
    const auto report = check_solid(s.decimated.mesh);
    CHECK(is_sound_solid(report));
    const double target = static_cast<double>(workpiece_triangles(s.stage, small_size));
    const auto count = static_cast<double>(s.decimated.mesh.triangle_count());
    CHECK(count >= 0.99 * target);
    CHECK(count <= 1.01 * target);
    // Decimation removed at least half of the fine RTIN: it is not that RTIN renamed.
    CHECK(s.decimated.fine_triangles >= 2 * s.decimated.mesh.triangle_count() * 9 / 10);
    CHECK(s.decimated.collapses > 0);
  }
}

TEST_CASE("decimated tops are height fields on the Z-map's samples", "[generator]") {
  for (const DecimatedStage& s : decimated_stages()) {
    INFO(s.stage.name);
    const Grid& grid = s.simulation.grid();
    const ncv::Mesh& mesh = s.decimated.mesh;
    // Collapses move no vertex: each is a grid sample at its Z-map height, or on the floor.
    for (const ncv::Vec3& v : mesh.vertices) {
      const int i = grid.nearest(v[0]);
      const int j = grid.nearest(v[1]);
      REQUIRE(grid.contains(i, j));
      REQUIRE(v[0] == grid.x(i));
      REQUIRE(v[1] == grid.y(j));
      const bool on_floor = v[2] == 0;
      REQUIRE((on_floor || v[2] == static_cast<double>(s.simulation.zmap()[grid.index(i, j)])));
    }
    // The top covers the rectangle exactly once: every triangle off the floor faces up (walls
    // are vertical, area 0), and their areas seen from +z add up to the rectangle's. A
    // collapse that folded the top over would leave a triangle facing down above the floor.
    double top_area = 0;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      const double area = projected_area(mesh, t);
      const bool on_floor =
          mesh.corner(t, 0)[2] == 0 && mesh.corner(t, 1)[2] == 0 && mesh.corner(t, 2)[2] == 0;
      if (on_floor) continue;
      REQUIRE(area >= 0);
      top_area += area;
    }
    CHECK(top_area == Approx(grid.x(grid.cells_x()) * grid.y(grid.cells_y())).epsilon(1e-12));
  }
}

TEST_CASE("every gouge centre stays a vertex at its depth after decimation", "[generator]") {
  for (const DecimatedStage& s : decimated_stages()) {
    const Grid& grid = s.simulation.grid();
    for (const GougeRecord& gouge : s.simulation.gouges()) {
      INFO(s.stage.name << " gouge at " << gouge.x << ", " << gouge.y);
      const float depth =
          s.simulation.zmap()[grid.index(grid.nearest(gouge.x), grid.nearest(gouge.y))];
      CHECK(depth <= gouge.nominal_z - gouge.depth + 1e-4);
      const auto& vertices = s.decimated.mesh.vertices;
      CHECK(std::any_of(vertices.begin(), vertices.end(), [&](const ncv::Vec3& v) {
        return v[0] == gouge.x && v[1] == gouge.y && v[2] == static_cast<double>(depth);
      }));
    }
  }
}

TEST_CASE("decimated workpieces stay within their tolerances of the RTIN workpieces",
          "[generator]") {
  for (const DecimatedStage& s : decimated_stages()) {
    INFO(s.stage.name);
    // Both approximate the same Z-map: the RTIN within its chord tolerance, the decimation
    // within its own bound of the fine RTIN, which is within its chord tolerance.
    const double bound = s.rtin.tolerance + s.decimated.tolerance + s.decimated.fine_tolerance;
    const double distance = ncv::gen::test::two_sided_distance(s.decimated.mesh, s.rtin.mesh);
    INFO("distance " << distance << ", bound " << bound);
    CHECK(distance <= bound);
    CHECK(s.decimated.tolerance == Approx(s.rtin.tolerance));
  }
}

TEST_CASE("decimation keeps every removed sample within its tolerance, even short of the target",
          "[generator]") {
  const DecimatedStage& finishing = decimated_stages().back();
  const Grid& grid = finishing.simulation.grid();
  const std::vector<float>& heights = finishing.simulation.zmap();
  std::vector<float> errors = chord_errors(grid, heights);
  propagate_errors(grid, errors);
  const std::vector<GridTriangle> fine =
      rtin_triangles(grid, errors, tolerance_for_count(grid, errors, 30'000));
  const std::vector<ncv::Vec3> samples = used_samples(grid, heights, fine);
  for (const double tolerance : {0.05, 0.005}) {
    INFO("tolerance " << tolerance);
    const Decimation decimated =
        decimate_height_field(grid, heights, fine, {}, {fine.size() / 4, tolerance});
    CHECK(decimated.triangles.size() < fine.size());
    CHECK(decimated.collapses > 0);
    const double distance =
        ncv::gen::test::largest_distance(samples, top_mesh(grid, heights, decimated.triangles));
    CHECK(distance <= tolerance * (1 + 1e-9));
    if (tolerance == 0.005) {
      // The bound stops the decimation before the target: scallops of 0.033 mm need more.
      CHECK(decimated.triangles.size() > fine.size() / 4 + 1000);
    }
  }
}

TEST_CASE("decimation keeps the border and the samples asked for", "[generator]") {
  const DecimatedStage& semi = decimated_stages()[1];
  const Grid& grid = semi.simulation.grid();
  const std::vector<float>& heights = semi.simulation.zmap();
  std::vector<float> errors = chord_errors(grid, heights);
  propagate_errors(grid, errors);
  const std::vector<GridTriangle> fine = rtin_triangles(grid, errors, 0.1f);
  // A sample of the fine RTIN away from the border (a gouge's centre is one: its error is
  // infinite).
  const std::uint32_t kept = fine[fine.size() / 2][0];
  const Decimation decimated = decimate_height_field(
      grid, heights, fine, {kept}, {fine.size() / 10, std::numeric_limits<double>::infinity()});
  const auto samples_of = [&](const std::vector<GridTriangle>& triangles) {
    std::vector<bool> used(grid.sample_count(), false);
    for (const GridTriangle& t : triangles) {
      for (const std::uint32_t s : t) used[s] = true;
    }
    return used;
  };
  const std::vector<bool> before = samples_of(fine);
  const std::vector<bool> after = samples_of(decimated.triangles);
  CHECK(after[kept]);
  for (int i = 0; i <= grid.cells_x(); ++i) {
    for (const int j : {0, grid.cells_y()})
      REQUIRE(after[grid.index(i, j)] == before[grid.index(i, j)]);
  }
  for (int j = 0; j <= grid.cells_y(); ++j) {
    for (const int i : {0, grid.cells_x()})
      REQUIRE(after[grid.index(i, j)] == before[grid.index(i, j)]);
  }
  // So the walls and bottom the closure adds are the fine RTIN's, and the solid is sound.
  CHECK(closure_triangle_count(grid, decimated.triangles) == closure_triangle_count(grid, fine));
  CHECK(is_sound_solid(check_solid(close_height_field(grid, heights, decimated.triangles, 0.0))));
}

TEST_CASE("the valence cap keeps the decimater's fans small", "[generator]") {
  for (const DecimatedStage& s : decimated_stages()) {
    INFO(s.stage.name);
    const ncv::Mesh& mesh = s.decimated.mesh;
    // On a closed mesh a vertex is in as many triangles as it has edges.
    std::vector<int> valence(mesh.vertex_count(), 0);
    for (const ncv::Triangle& t : mesh.triangles) {
      for (const std::uint32_t v : t) ++valence[v];
    }
    const Grid& grid = s.simulation.grid();
    std::vector<int> top;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
      const ncv::Vec3& p = mesh.vertices[v];
      const bool border = p[0] == 0 || p[1] == 0 || p[0] == grid.x(grid.cells_x()) ||
                          p[1] == grid.y(grid.cells_y());
      if (!border && p[2] > 0) top.push_back(valence[v]);
    }
    std::sort(top.begin(), top.end());
    // The cap (32) is checked when a collapse is rated; a rating goes stale when its target
    // gains edges from the other side, so a few vertices pass it. Without the cap the small
    // finishing part has a vertex of 135 edges.
    CHECK(top.back() <= 64);
  }
}

TEST_CASE("the decimated nominal is a sound solid of 17,600 triangles near the RTIN nominal",
          "[generator]") {
  const MouldCore part = make_mould_core(1);
  const DecimatedSolid nominal = decimated_nominal_mesh(part);
  CHECK(is_sound_solid(check_solid(nominal.mesh)));
  CHECK(nominal.mesh.triangle_count() <= decimated_nominal_triangles);
  CHECK(nominal.mesh.triangle_count() >= decimated_nominal_triangles - 2);
  const NominalOptions rtin;
  const double distance =
      ncv::gen::test::two_sided_distance(nominal.mesh, nominal_mesh(part, rtin));
  INFO("distance " << distance);
  CHECK(distance <= rtin.chord_tolerance + nominal.tolerance + nominal.fine_tolerance);
}

TEST_CASE("decimated parts depend only on their inputs", "[generator]") {
  const DecimatedStage& roughing = decimated_stages().front();
  const DecimatedSolid again = decimated_workpiece_mesh(
      roughing.simulation, workpiece_triangles(roughing.stage, small_size));
  CHECK(again.mesh.vertices == roughing.decimated.mesh.vertices);
  CHECK(again.mesh.triangles == roughing.decimated.mesh.triangles);
  DecimatedOptions finer;
  finer.refinement = 3;
  const DecimatedSolid other = decimated_workpiece_mesh(
      roughing.simulation, workpiece_triangles(roughing.stage, small_size), finer);
  CHECK(other.mesh.triangles != roughing.decimated.mesh.triangles);
}
