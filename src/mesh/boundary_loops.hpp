// The boundary loops of an open surface, walked on OpenMesh's halfedge structure: the
// halfedges without a face form closed loops (each boundary halfedge's next is the next
// one along the hole), so a hole in a nominal is reported as where it is and how long,
// not only as a count of open edges (docs/METHOD.md: an open nominal is signed by the winding
// number).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/bounding_box.hpp"
#include "mesh/tri_mesh.hpp"

namespace ncv {

struct BoundaryLoop {
  std::uint64_t edges = 0;
  double length = 0;    // the sum of its edges' lengths, in model units
  BoundingBox box;      // of its vertices
  Vec3 start{0, 0, 0};  // a vertex on it: the start of its lowest-numbered halfedge
};

// Every boundary loop of `mesh`, ordered by their lowest-numbered halfedge; empty for a
// closed mesh. Coordinates are those of the mesh's points.
std::vector<BoundaryLoop> boundary_loops(const TriMesh& mesh);

// The same loops with every coordinate moved by `offset` (from a local frame to the model's).
std::vector<BoundaryLoop> translated(std::vector<BoundaryLoop> loops, Vec3 offset);

}  // namespace ncv
