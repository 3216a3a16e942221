// A binary module for OpenMesh's decimater that keeps a height field a height field: a halfedge
// collapse is legal only if every face it leaves keeps a positive area seen from +z. A
// decimated Z-map top then still covers its rectangle exactly once, so it cannot fold over or
// cut through itself, and walls closed onto its fixed border make a solid without
// self-intersections. OpenMesh's ModNormalFlippingT bounds the normals' turn instead, which on
// the near-vertical walls of a step or a drafted flank lets a face tip past vertical.
//
// Exact on grid samples: their x and y are multiples of the spacing, a power of two times a
// small odd integer, so the cross products below are exact and zero area means zero.
#pragma once

#include <OpenMesh/Tools/Decimater/ModBaseT.hh>

namespace ncv::gen {

template <class MeshT>
class HeightFieldGuardT : public OpenMesh::Decimater::ModBaseT<MeshT> {
 public:
  DECIMATING_MODULE(HeightFieldGuardT, MeshT, HeightFieldGuard);

  explicit HeightFieldGuardT(MeshT& mesh) : Base(mesh, true) {}

  float collapse_priority(const CollapseInfo& ci) override {
    const Mesh& mesh = Base::mesh();
    // Each face around v0 is (v0, to(h), to(next(h))) for an outgoing halfedge h of v0; after
    // the collapse v0 stands at p1. The faces beside the collapsed edge go.
    for (const auto h : mesh.voh_range(ci.v0)) {
      const auto face = mesh.face_handle(h);
      if (!face.is_valid() || face == ci.fl || face == ci.fr) continue;
      const auto& b = mesh.point(mesh.to_vertex_handle(h));
      const auto& c = mesh.point(mesh.to_vertex_handle(mesh.next_halfedge_handle(h)));
      const auto& a = ci.p1;
      const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
      if (!(area > 0)) return static_cast<float>(Base::ILLEGAL_COLLAPSE);
    }
    return static_cast<float>(Base::LEGAL_COLLAPSE);
  }
};

}  // namespace ncv::gen
