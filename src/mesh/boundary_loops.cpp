#include "mesh/boundary_loops.hpp"

#include <unordered_set>

#include "util/ordered_reduce.hpp"

namespace ncv {

// The boundary halfedges are found in parallel (a closed mesh has none, and that scan is
// all it costs), then each one not yet seen starts a loop, walked by next until it comes
// back. The walk stops after as many steps as there are boundary halfedges, so a broken
// structure cannot hang it.
std::vector<BoundaryLoop> boundary_loops(const TriMesh& mesh) {
  using Halfedges = std::vector<int>;
  const Halfedges boundary = ordered_reduce(
      mesh.n_halfedges(), std::size_t{1} << 16, Halfedges{},
      [&](std::size_t begin, std::size_t end) {
        Halfedges part;
        for (std::size_t i = begin; i < end; ++i) {
          if (mesh.is_boundary(TriMesh::HalfedgeHandle(static_cast<int>(i)))) {
            part.push_back(static_cast<int>(i));
          }
        }
        return part;
      },
      [](Halfedges& all, const Halfedges& part) {
        all.insert(all.end(), part.begin(), part.end());
      });
  std::vector<BoundaryLoop> loops;
  std::unordered_set<int> seen;
  for (const int i : boundary) {
    if (seen.contains(i)) continue;
    const auto first = TriMesh::HalfedgeHandle(i);
    BoundaryLoop loop;
    loop.start = mesh.point(mesh.from_vertex_handle(first));
    auto h = first;
    for (std::size_t steps = 0; steps < boundary.size(); ++steps) {
      seen.insert(h.idx());
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
