// A binary module for OpenMesh's decimater that refuses a collapse leaving a vertex with more
// than `cap` edges. On a flat face every collapse costs nothing by the quadric, so without it
// the decimater fans whole planes out of single vertices (valences of 300 to 600 seen on the
// mould core), and as each collapse re-rates every outgoing edge of every neighbour, its time
// grows with the square of the valence: 33 s instead of about 1 s for the small finishing part.
// CAD and CAM exports have fans too, so the cap is set far above the 6 of a regular mesh.
//
// The decimater rates a vertex's collapses when its neighbourhood changes, not when the
// collapse's target gains edges from its other side, so a rating can go stale and a few
// vertices end above the cap (at most 57 on the large parts).
#pragma once

#include <OpenMesh/Tools/Decimater/ModBaseT.hh>

namespace ncv::gen {

template <class MeshT>
class ValenceCapT : public OpenMesh::Decimater::ModBaseT<MeshT> {
 public:
  DECIMATING_MODULE(ValenceCapT, MeshT, ValenceCap);

  explicit ValenceCapT(MeshT& mesh) : Base(mesh, true) {}

  void set_cap(unsigned cap) { cap_ = cap; }

  float collapse_priority(const CollapseInfo& ci) override {
    Mesh& mesh = Base::mesh();
    // v1 keeps its edges and takes v0's, less the collapsed edge (counted at both ends) and
    // one edge to each vertex the two share (vl and vr where they exist).
    const unsigned shared = (ci.vl.is_valid() ? 1 : 0) + (ci.vr.is_valid() ? 1 : 0);
    const unsigned valence = mesh.valence(ci.v0) + mesh.valence(ci.v1) - 2 - shared;
    return static_cast<float>(valence > cap_ ? Base::ILLEGAL_COLLAPSE : Base::LEGAL_COLLAPSE);
  }

 private:
  unsigned cap_ = 32;
};

}  // namespace ncv::gen
