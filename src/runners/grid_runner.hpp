// The grid step (`ncverify grid-build`, and run's grid phase in each direction): the mesh the
// distances are measured to, prepared (topology, orientation, sign method) and indexed by its
// background grid (paper §3.3).
#pragma once

#include <string>

#include "search/grid_builder.hpp"
#include "search/indexed_reference.hpp"

namespace ncv {

struct IndexedSurface {
  IndexedReference reference;
  GridStatistics statistics;
  double seconds = 0;
};

IndexedSurface index_surface(std::shared_ptr<const Mesh> mesh, const std::string& source,
                             const GridOptions& options,
                             SurfaceHolding holding = SurfaceHolding::halfedges_where_possible);
// The topology, the sign method it implies and the grid, on stderr.
void log_grid(const IndexedSurface& indexed);

// `ncverify grid-build MESH -o OUT`.
struct GridJob {
  std::string mesh;
  std::string output;
  GridOptions options;
};
void run_grid_build(const GridJob& job);

}  // namespace ncv
