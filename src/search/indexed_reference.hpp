// The reference surface prepared for distance queries: the mesh the distances are measured to
// (the nominal, or the workpiece when measuring in reverse), its ReferenceSurface (local
// frame, topology, normals, sign method) and its background grid (paper §3.3). grid-build
// makes it, the grid file stores it, and a SearchIndex can only be made from one, so a search
// always reads the grid of the triangles it tests.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "mesh/mesh.hpp"
#include "reference/reference_surface.hpp"
#include "search/background_grid.hpp"
#include "search/grid_builder.hpp"

namespace ncv {

struct IndexedReference {
  // The mesh as read, in global coordinates (what the grid file stores); shared, as run's
  // reverse direction measures against the workpiece its forward samples hold.
  std::shared_ptr<const Mesh> mesh;
  std::string source;
  std::uint64_t hash = 0;  // mesh_hash(mesh)
  std::unique_ptr<ReferenceSurface> surface;
  BackgroundGrid grid;  // in the surface's local frame
};

// Prepares the surface (topology, orientation, sign method) and builds its grid.
IndexedReference index_reference(std::shared_ptr<const Mesh> mesh, const std::string& source,
                                 const GridOptions& options = {},
                                 GridStatistics* statistics = nullptr,
                                 SurfaceHolding holding = SurfaceHolding::halfedges_where_possible);
IndexedReference index_reference(Mesh mesh, const std::string& source,
                                 const GridOptions& options = {},
                                 GridStatistics* statistics = nullptr,
                                 SurfaceHolding holding = SurfaceHolding::halfedges_where_possible);

}  // namespace ncv
