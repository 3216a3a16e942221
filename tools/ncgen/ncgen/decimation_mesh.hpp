// The mesh the decimater works on: ncverify's double-precision TriMesh with OpenMesh's own
// collapse test replaced by an allocation-free one. OpenMesh 9's
// TriConnectivity::is_collapse_ok copies both one-rings into heap vectors and compares them on
// every call, and the decimater calls it for every outgoing edge of every neighbour after each
// collapse: `perf` put it, its allocations and its memcmp at 55 % of the decimation's time on
// the small finishing part. This one marks one ring with the vertex status's `tagged` bit, as
// OpenMesh did before, and decides the same: DecimaterT calls `mesh_.is_collapse_ok` on its
// mesh type, so this definition hides the base class's.
#pragma once

#include "mesh/tri_mesh.hpp"

namespace ncv::gen {

struct DecimationMesh : TriMesh {
  // Needs vertex, edge and face status (the decimater requests them). Legal when the collapse
  // of v0 into v1 keeps the mesh a manifold: the edge and its ends are live, a face beside the
  // edge does not have its two other edges on the boundary, the edge has a face on at least one
  // side, v0 and v1 share no neighbour but the far corners of those faces, and an edge between
  // two boundary vertices is itself a boundary edge.
  bool is_collapse_ok(HalfedgeHandle v0v1) {
    if (status(edge_handle(v0v1)).deleted()) return false;
    const HalfedgeHandle v1v0 = opposite_halfedge_handle(v0v1);
    const VertexHandle v0 = to_vertex_handle(v1v0);
    const VertexHandle v1 = to_vertex_handle(v0v1);
    if (status(v0).deleted() || status(v1).deleted()) return false;

    VertexHandle vl, vr;
    if (!far_corner(v0v1, vl) || !far_corner(v1v0, vr)) return false;
    if (vl == vr) return false;  // equal, or no face on either side

    for (const VertexHandle v : vv_range(v0)) status(v).set_tagged(false);
    for (const VertexHandle v : vv_range(v1)) status(v).set_tagged(true);
    for (const VertexHandle v : vv_range(v0)) {
      if (status(v).tagged() && v != vl && v != vr) return false;
    }
    return !(is_boundary(v0) && is_boundary(v1) && !is_boundary(v0v1) && !is_boundary(v1v0));
  }

 private:
  // The far corner of the face on h's side, into `far` (left invalid on the boundary); false
  // when that face's two other edges both lie on the boundary.
  bool far_corner(HalfedgeHandle h, VertexHandle& far) {
    if (is_boundary(h)) return true;
    const HalfedgeHandle h1 = next_halfedge_handle(h);
    const HalfedgeHandle h2 = next_halfedge_handle(h1);
    far = to_vertex_handle(h1);
    return !(is_boundary(opposite_halfedge_handle(h1)) &&
             is_boundary(opposite_halfedge_handle(h2)));
  }
};

}  // namespace ncv::gen
