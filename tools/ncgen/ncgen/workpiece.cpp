#include "ncgen/workpiece.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ncgen/height_solid.hpp"
#include "ncgen/nominal_part.hpp"
#include "ncgen/part_size.hpp"
#include "ncgen/rtin.hpp"

namespace ncv::gen {

Workpiece workpiece_mesh(const MillingSimulation& simulation, std::size_t triangles) {
  const Grid& grid = simulation.grid();
  std::vector<float> errors = chord_errors(grid, simulation.zmap());
  // The deepest sample of every gouge stays a vertex, so that no tolerance smooths it away.
  for (const GougeRecord& gouge : simulation.gouges()) {
    errors[grid.index(grid.nearest(gouge.x), grid.nearest(gouge.y))] =
        std::numeric_limits<float>::infinity();
  }
  propagate_errors(grid, errors);
  Workpiece workpiece;
  workpiece.tolerance =
      std::min(tolerance_for_count(grid, errors, triangles), coarsest_workpiece_tolerance);
  workpiece.mesh = height_field_solid(grid, simulation.zmap(), errors, workpiece.tolerance, 0.0);
  return workpiece;
}

void mill_part(const MouldCore& part, double size, const std::vector<MillingStage>& stages,
               const std::function<void(const MillingStage&, const MillingSimulation&)>& visit) {
  const Grid grid = part_grid(part, zmap_level(size));
  MillingSimulation simulation(grid, sample_heights(grid, part), part.flat_levels(), stock_height);
  for (const MillingStage& stage : stages) {
    simulation.mill(stage);
    visit(stage, simulation);
  }
}

std::size_t workpiece_triangles(const MillingStage& stage, double size) {
  return static_cast<std::size_t>(std::llround(static_cast<double>(stage.paper_triangles) * size));
}

}  // namespace ncv::gen
