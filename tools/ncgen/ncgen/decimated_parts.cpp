#include "ncgen/decimated_parts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ncgen/decimation.hpp"
#include "ncgen/height_solid.hpp"
#include "ncgen/nominal_part.hpp"
#include "ncgen/rtin.hpp"
#include "ncgen/workpiece.hpp"

namespace ncv::gen {

DecimatedSolid decimated_height_solid(const Grid& grid, const std::vector<float>& heights,
                                      const std::vector<float>& errors,
                                      const std::vector<std::uint32_t>& keep, std::size_t triangles,
                                      float chord_tolerance, const DecimatedOptions& options) {
  DecimatedSolid solid;
  const std::size_t coarse =
      std::max(triangles, rtin_triangle_count(grid, errors, chord_tolerance));
  const auto fine_target =
      static_cast<std::size_t>(std::llround(options.refinement * static_cast<double>(coarse)));
  solid.fine_tolerance = tolerance_for_count(grid, errors, fine_target);
  const std::vector<GridTriangle> fine = rtin_triangles(grid, errors, solid.fine_tolerance);
  solid.fine_triangles = fine.size();
  // The walls and bottom stand on the border samples, which decimation keeps: their share of
  // the budget is known before it starts.
  const std::size_t closure = closure_triangle_count(grid, fine);
  solid.tolerance = options.tolerance_factor * chord_tolerance;
  DecimationOptions decimation;
  decimation.target = triangles > closure ? triangles - closure : 0;
  decimation.tolerance = solid.tolerance;
  Decimation top = decimate_height_field(grid, heights, fine, keep, decimation);
  solid.collapses = top.collapses;
  solid.mesh = close_height_field(grid, heights, top.triangles, 0.0);
  return solid;
}

DecimatedSolid decimated_workpiece_mesh(const MillingSimulation& simulation, std::size_t triangles,
                                        const DecimatedOptions& options) {
  const Grid& grid = simulation.grid();
  std::vector<float> errors = chord_errors(grid, simulation.zmap());
  std::vector<std::uint32_t> keep;
  for (const GougeRecord& gouge : simulation.gouges()) {
    keep.push_back(grid.index(grid.nearest(gouge.x), grid.nearest(gouge.y)));
    errors[keep.back()] = std::numeric_limits<float>::infinity();
  }
  propagate_errors(grid, errors);
  const float chord_tolerance =
      std::min(tolerance_for_count(grid, errors, triangles), coarsest_workpiece_tolerance);
  return decimated_height_solid(grid, simulation.zmap(), errors, keep, triangles, chord_tolerance,
                                options);
}

DecimatedSolid decimated_nominal_mesh(const MouldCore& part, std::size_t triangles,
                                      const DecimatedOptions& options) {
  const Grid grid = part_grid(part, NominalOptions{}.level);
  const std::vector<float> heights = sample_heights(grid, part);
  std::vector<float> errors = chord_errors(grid, heights);
  propagate_errors(grid, errors);
  return decimated_height_solid(grid, heights, errors, {}, triangles,
                                tolerance_for_count(grid, errors, triangles), options);
}

}  // namespace ncv::gen
