// The paper-scale workload the benchmark programs measure: a workpiece sampled (scheme I) at
// a fraction of its diagonal (0.1 %, the paper's δ, by default) against a nominal's grid.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "grid_builder.hpp"
#include "mesh_reader.hpp"
#include "sampling.hpp"

namespace ncv::bench {

struct Workload {
  std::unique_ptr<NominalSurface> nominal;
  UniformGrid grid;
  std::vector<Vec3> points;  // the samples, in the global frame
};

inline Workload load_workload(const char* workpiece_path, const char* nominal_path,
                              double step_fraction = 0.001) {
  Workload w;
  w.nominal = std::make_unique<NominalSurface>(read_mesh(nominal_path), nominal_path);
  w.grid = build_uniform_grid(*w.nominal);
  Mesh workpiece = read_mesh(workpiece_path);
  const double step = step_fraction * bounding_box(workpiece).diagonal();
  w.points = sample_mesh(std::move(workpiece), step, SamplingScheme::all).positions;
  return w;
}

}  // namespace ncv::bench
