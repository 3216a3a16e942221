#include "search/indexed_reference.hpp"

namespace ncv {

IndexedReference index_reference(std::shared_ptr<const Mesh> mesh, const std::string& source,
                                 const GridOptions& options, GridStatistics* statistics,
                                 SurfaceHolding holding) {
  IndexedReference reference;
  reference.source = source;
  reference.mesh = std::move(mesh);
  reference.hash = mesh_hash(*reference.mesh);
  reference.surface = std::make_unique<ReferenceSurface>(*reference.mesh, source, holding);
  reference.grid = build_background_grid(*reference.surface, options, statistics);
  return reference;
}

IndexedReference index_reference(Mesh mesh, const std::string& source, const GridOptions& options,
                                 GridStatistics* statistics, SurfaceHolding holding) {
  return index_reference(std::make_shared<const Mesh>(std::move(mesh)), source, options, statistics,
                         holding);
}

}  // namespace ncv
