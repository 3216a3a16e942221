// Face normals and the angle-weighted pseudonormals of vertices and edges (Baerentzen &
// Aanaes 2005), which sign a distance by the feature its closest point lies on
// (docs/METHOD.md).
//
// A vertex sums the unit normals of its faces weighted by the face angle there, an edge sums
// the normals of the faces along it. Degenerate faces (is_degenerate_triangle) have a zero
// normal and contribute nothing: they cannot outvote their neighbours with a noisy direction.
//
// Two ways, with the same values to the bit: on OpenMesh's halfedge structure (a face's
// halfedges give its corners, a vertex's outgoing halfedges its faces and their angles, an
// edge's two halfedges its faces), for a surface OpenMesh holds (halfedge_mesh.hpp); and on
// the plain arrays and their edge incidence, for one it cannot (a third face on an edge).
// Both add each sum's terms in ascending face order from zero, so the sums, and with them
// every sign, do not depend on the way or on the thread count.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "geometry/closest_point.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_corners.hpp"
#include "mesh/mesh_topology.hpp"
#include "mesh/tri_mesh.hpp"
#include "util/buffer.hpp"

namespace ncv {

struct Pseudonormals {
  Buffer<Vec3> face;                   // per triangle: unit, or zero when degenerate
  std::vector<Vec3> vertex;            // per vertex: unit, or zero
  std::vector<Vec3> edge;              // per undirected edge: unit, or zero
  Buffer<std::uint32_t> edge_of_slot;  // per triangle edge 3t + k: its edge, or kNoEdge
};

// Face normals only (the first step of both ways below), from each triangle's corners.
Buffer<Vec3> face_normals(MeshCorners corners);

// On the halfedge structure built by halfedge_mesh from `incidence`.
Pseudonormals halfedge_pseudonormals(const TriMesh& mesh, const EdgeIncidence& incidence);

// On the arrays: `incidence` is `mesh`'s edge incidence (its edge_of_slot becomes the
// result's).
Pseudonormals array_pseudonormals(const Mesh& mesh, EdgeIncidence incidence);

// True when every vertex's pseudonormal can be found by walking around it (FanPseudonormals):
// every edge on two triangles, one fan of triangles at every vertex, no triangle that repeats
// a corner (it has no edges to walk across).
bool fans_walkable(const EdgeIncidence& incidence, const TopologyReport& topology);

// The arrays' normals of a surface whose fans are walkable, each worked out when it is asked
// for rather than all up front: signing asks for few (the finishing workpiece, measured from
// the nominal's 1.22 M samples: 53 % of them end on a face, 7 % on an edge, 0.1 % on a
// vertex, the others signed without one), and the up-front way spent most of its 0.11 s in the 3.7
// M corner angles. The values are the arrays' (array_pseudonormals) to the bit: a face's by the
// same formula, a vertex's terms gathered around its fan and added in ascending face order
// from zero, an edge's over its slots, as there.
class FanPseudonormals {
 public:
  // From the edge incidence of a surface whose fans are walkable (fans_walkable), after any
  // flip: each slot's partner across its edge is all that is kept (4 bytes a slot, where the
  // incidence is 10; 21 MB less for the 1.25 M-triangle workpiece).
  explicit FanPseudonormals(const EdgeIncidence& incidence);

  // `mesh` and `corners` are the surface's (after any flip, as `incidence`).
  static Vec3 face(MeshCorners corners, std::size_t triangle);
  // At corner k of `triangle`.
  Vec3 vertex(const Mesh& mesh, std::size_t triangle, int k) const;
  // Along slot k of `triangle` (from its corner k to the next).
  Vec3 edge(MeshCorners corners, std::size_t triangle, int k) const;

 private:
  Buffer<std::uint32_t> partner_;  // per slot: the other slot on its edge
};

}  // namespace ncv
