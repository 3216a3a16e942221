// The simulated milling and the workpieces made of its Z-maps.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "ncgen/analytic_parts.hpp"
#include "ncgen/nominal_part.hpp"
#include "ncgen/part_size.hpp"
#include "ncgen/workpiece.hpp"
#include "test_generator_checks.hpp"

using namespace ncv::gen;

namespace {

struct StageSnapshot {
  MillingStage stage;
  std::vector<float> zmap;
  std::vector<GougeRecord> gouges;
  Workpiece at_size;         // small_size
  Workpiece at_double_size;  // 2 * small_size
};

struct MilledCore {
  MouldCore part;
  Grid grid;
  std::vector<float> nominal;
  std::vector<StageSnapshot> stages;
};

// Milling the core takes about a second: once for all tests.
const MilledCore& milled_core() {
  static const MilledCore core = [] {
    MilledCore milled{make_mould_core(1), {}, {}, {}};
    mill_part(milled.part, small_size, mould_core_stages(),
              [&](const MillingStage& stage, const MillingSimulation& simulation) {
                milled.grid = simulation.grid();
                milled.nominal = simulation.nominal();
                milled.stages.push_back(
                    {stage, simulation.zmap(), simulation.gouges(),
                     workpiece_mesh(simulation, workpiece_triangles(stage, small_size)),
                     workpiece_mesh(simulation, workpiece_triangles(stage, 2 * small_size))});
              });
    return milled;
  }();
  return core;
}

double distance_to_nearest_gouge(const StageSnapshot& snapshot, double x, double y) {
  double nearest = INFINITY;
  for (const GougeRecord& g : snapshot.gouges)
    nearest = std::min(nearest, std::hypot(x - g.x, y - g.y));
  return nearest;
}

double largest_gouge_radius(const StageSnapshot& snapshot) {
  double radius = 0;
  for (const GougeRecord& g : snapshot.gouges) radius = std::max(radius, g.cutter.radius);
  return radius;
}

// Height of the mesh's upward faces above (x, y), by barycentric interpolation.
double mesh_height(const ncv::Mesh& mesh, double x, double y) {
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    if (ncv::area_vector(mesh, t)[2] <= 0) continue;
    const ncv::Vec3 a = mesh.corner(t, 0);
    const ncv::Vec3 b = mesh.corner(t, 1);
    const ncv::Vec3 c = mesh.corner(t, 2);
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
    const double wb = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / area;
    const double wc = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / area;
    if (wb >= -1e-12 && wc >= -1e-12 && wb + wc <= 1 + 1e-12) {
      return a[2] + wb * (b[2] - a[2]) + wc * (c[2] - a[2]);
    }
  }
  return NAN;
}

// A flat plate at z = 10 on a 20 mm grid, finished with one ball-end raster.
std::vector<float> mill_flat_plate(double radius, double stepover, double& actual_stepover) {
  const Grid grid = tiled_grid(1, 1, 20.0, 8);
  MillingSimulation simulation(grid, std::vector<float>(grid.sample_count(), 10.0f), {10.0}, 12.0);
  MillingStage stage;
  stage.cutter = {CutterShape::ball_end, radius};
  stage.stepover = stepover;
  stage.feed = grid.spacing;
  simulation.mill(stage);
  actual_stepover = std::round(stepover / grid.spacing) * grid.spacing;
  return simulation.zmap();
}

}  // namespace

TEST_CASE("workpieces of every stage are closed outward manifolds on the nominal's frame",
          "[generator]") {
  for (const StageSnapshot& snapshot : milled_core().stages) {
    INFO(snapshot.stage.name);
    for (const Workpiece* workpiece : {&snapshot.at_size, &snapshot.at_double_size}) {
      const test::SolidReport report = test::check_solid(workpiece->mesh);
      CHECK(report.unpaired_edges == 0);
      CHECK(report.repeated_edges == 0);
      CHECK(report.non_manifold_vertices == 0);
      CHECK(report.degenerate_triangles == 0);
      CHECK(report.euler == 2);
      CHECK(report.volume > 0);
      const ncv::BoundingBox box = ncv::bounding_box(workpiece->mesh);
      CHECK(box.min[0] == 0);
      CHECK(box.min[1] == 0);
      CHECK(box.min[2] == 0);
      CHECK(box.max[0] == Approx(120));
      CHECK(box.max[1] == Approx(80));
      CHECK(box.max[2] <= stock_height);
    }
  }
}

TEST_CASE("workpiece triangle counts follow the size parameter", "[generator]") {
  int scaled = 0;
  for (const StageSnapshot& snapshot : milled_core().stages) {
    INFO(snapshot.stage.name);
    const auto small = static_cast<double>(snapshot.at_size.mesh.triangle_count());
    const auto twice = static_cast<double>(snapshot.at_double_size.mesh.triangle_count());
    CHECK(twice >= small);
    CHECK(snapshot.at_double_size.tolerance <= snapshot.at_size.tolerance);
    // Small roughing workpieces are held back by the coarsest tolerance (0.5 mm).
    if (snapshot.at_size.tolerance < 0.5f) {
      const auto target = static_cast<double>(workpiece_triangles(snapshot.stage, small_size));
      CHECK(small == Approx(target).epsilon(0.1));
      CHECK(twice / small == Approx(2).epsilon(0.15));
      ++scaled;
    }
  }
  CHECK(scaled == 2);  // semi-finishing and finishing
}

TEST_CASE("finishing leaves scallops of R - sqrt(R^2 - (s/2)^2) on the flat base", "[generator]") {
  const MilledCore& core = milled_core();
  const StageSnapshot& finishing = core.stages.back();
  const double expected = scallop_height(finishing.stage.cutter.radius, finishing.stage.stepover);
  // A patch of the base clear of features and gouges: x 20..50, y 2..7.
  double lowest = INFINITY;
  double highest = -INFINITY;
  for (int j = core.grid.nearest(2); j <= core.grid.nearest(7); ++j) {
    for (int i = core.grid.nearest(20); i <= core.grid.nearest(50); ++i) {
      const double excess =
          finishing.zmap[core.grid.index(i, j)] - core.nominal[core.grid.index(i, j)];
      lowest = std::min(lowest, excess);
      highest = std::max(highest, excess);
    }
  }
  CHECK(lowest == Approx(0).margin(1e-5));
  CHECK(highest == Approx(expected).margin(1e-5));
  CHECK(expected == Approx(0.0329).margin(1e-4));
}

TEST_CASE("ball-end scallops on a plate match the formula", "[generator]") {
  const auto [radius, stepover] = GENERATE(std::pair{1.5, 0.625}, std::pair{3.0, 1.25},
                                           std::pair{1.0, 0.3125}, std::pair{2.0, 0.9375});
  double actual = 0;
  const std::vector<float> zmap = mill_flat_plate(radius, stepover, actual);
  const Grid grid = tiled_grid(1, 1, 20.0, 8);
  const double expected = scallop_height(radius, actual);
  // Away from the plate's rim, where the path runs out.
  const int margin = grid.nearest(radius + actual);
  double lowest = INFINITY;
  double highest = -INFINITY;
  for (int j = margin; j <= grid.cells_y() - margin; ++j) {
    for (int i = margin; i <= grid.cells_x() - margin; ++i) {
      lowest = std::min(lowest, zmap[grid.index(i, j)] - 10.0);
      highest = std::max(highest, zmap[grid.index(i, j)] - 10.0);
    }
  }
  CHECK(lowest == Approx(0).margin(1e-5));
  CHECK(highest == Approx(expected).margin(1e-5));
}

TEST_CASE("each stage keeps its allowance except at the recorded gouges", "[generator]") {
  const MilledCore& core = milled_core();
  for (const StageSnapshot& snapshot : core.stages) {
    INFO(snapshot.stage.name);
    const double clear = largest_gouge_radius(snapshot) + core.grid.spacing;
    double thinnest = INFINITY;
    double deepest = INFINITY;
    for (int j = 0; j <= core.grid.cells_y(); ++j) {
      for (int i = 0; i <= core.grid.cells_x(); ++i) {
        const double excess =
            snapshot.zmap[core.grid.index(i, j)] - core.nominal[core.grid.index(i, j)];
        deepest = std::min(deepest, excess);
        if (distance_to_nearest_gouge(snapshot, core.grid.x(i), core.grid.y(j)) > clear) {
          thinnest = std::min(thinnest, excess);
        }
      }
    }
    // The allowance is along the normal, so vertically there is at least as much.
    CHECK(thinnest >= snapshot.stage.allowance - 1e-4);
    CHECK(deepest == Approx(-0.3).margin(1e-4));  // the roughing gouge persists
  }
}

TEST_CASE("gouges are where recorded, below the nominal, in Z-map and mesh", "[generator]") {
  const MilledCore& core = milled_core();
  const StageSnapshot& finishing = core.stages.back();
  REQUIRE(finishing.gouges.size() == 3);
  for (const GougeRecord& gouge : finishing.gouges) {
    INFO(gouge.stage << " gouge at " << gouge.x << ", " << gouge.y);
    CHECK(gouge.depth >= 0.1);
    CHECK(gouge.depth <= 0.3);
    // On a horizontal face of the nominal, so the depth below it is exact.
    CHECK(core.part.height(gouge.x, gouge.y) == Approx(gouge.nominal_z));
    CHECK(core.part.height(gouge.x + 1, gouge.y - 1) == Approx(gouge.nominal_z));
    const std::size_t sample =
        core.grid.index(core.grid.nearest(gouge.x), core.grid.nearest(gouge.y));
    CHECK(finishing.zmap[sample] == Approx(gouge.nominal_z - gouge.depth).margin(1e-4));
    CHECK(mesh_height(finishing.at_size.mesh, gouge.x, gouge.y) ==
          Approx(gouge.nominal_z - gouge.depth).margin(1e-4));
  }
}

TEST_CASE("roughing leaves millimetres where its flat end mill cannot reach", "[generator]") {
  const MilledCore& core = milled_core();
  const Pocket& pocket = core.part.pocket;
  const auto leftover = [&](const StageSnapshot& snapshot, double x, double y) {
    const std::size_t s = core.grid.index(core.grid.nearest(x), core.grid.nearest(y));
    return snapshot.zmap[s] - core.nominal[s];
  };
  const double corner_x = pocket.min_x + pocket.wall_width;  // a floor corner
  const double corner_y = pocket.min_y + pocket.wall_width;
  CHECK(leftover(core.stages[0], corner_x + 0.1, corner_y + 0.1) > 2.0);
  // Finishing reaches the pocket floor's middle but not quite its sharp corner.
  CHECK(leftover(core.stages[2], (pocket.min_x + pocket.max_x) / 2, pocket.min_y + 3) < 0.05);
  CHECK(leftover(core.stages[2], corner_x + 0.1, corner_y + 0.1) > 0.3);
}

TEST_CASE("workpieces depend only on the seed and size", "[generator]") {
  std::uint64_t hash = 0;
  std::vector<MillingStage> stages = mould_core_stages();
  mill_part(make_mould_core(1), small_size, stages,
            [&](const MillingStage& stage, const MillingSimulation& simulation) {
              if (stage.name == stages.back().name) {
                hash = ncv::mesh_hash(
                    workpiece_mesh(simulation, workpiece_triangles(stage, small_size)).mesh);
              }
            });
  CHECK(hash == ncv::mesh_hash(milled_core().stages.back().at_size.mesh));
}
