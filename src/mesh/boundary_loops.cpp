#include "mesh/boundary_loops.hpp"

namespace ncv {

// One pass over the halfedges: a boundary halfedge not yet seen starts a loop, walked by
// next until it comes back. The walk stops after as many steps as there are halfedges, so a
// broken structure cannot hang it.
std::vector<BoundaryLoop> boundary_loops(const TriMesh& mesh) {
  std::vector<BoundaryLoop> loops;
  std::vector<bool> seen(mesh.n_halfedges(), false);
  for (std::size_t i = 0; i < mesh.n_halfedges(); ++i) {
    const auto first = TriMesh::HalfedgeHandle(static_cast<int>(i));
    if (seen[i] || !mesh.is_boundary(first)) continue;
    BoundaryLoop loop;
    loop.start = mesh.point(mesh.from_vertex_handle(first));
    auto h = first;
    for (std::size_t steps = 0; steps < mesh.n_halfedges(); ++steps) {
      seen[static_cast<std::size_t>(h.idx())] = true;
      const Vec3 from = mesh.point(mesh.from_vertex_handle(h));
      const Vec3 to = mesh.point(mesh.to_vertex_handle(h));
      loop.box.extend(from);
      loop.length += norm(to - from);
      ++loop.edges;
      h = mesh.next_halfedge_handle(h);
      if (h == first || !h.is_valid()) break;
    }
    loops.push_back(loop);
  }
  return loops;
}

std::vector<BoundaryLoop> translated(std::vector<BoundaryLoop> loops, Vec3 offset) {
  for (BoundaryLoop& loop : loops) {
    loop.box.min = loop.box.min + offset;
    loop.box.max = loop.box.max + offset;
    loop.start = loop.start + offset;
  }
  return loops;
}

}  // namespace ncv
