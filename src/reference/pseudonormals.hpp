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
#include <vector>

#include "geometry/closest_point.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_topology.hpp"
#include "mesh/tri_mesh.hpp"
#include "util/buffer.hpp"

namespace ncv {

struct Pseudonormals {
  Buffer<Vec3> face;                        // per triangle: unit, or zero when degenerate
  std::vector<Vec3> vertex;                 // per vertex: unit, or zero
  std::vector<Vec3> edge;                   // per undirected edge: unit, or zero
  std::vector<std::uint32_t> edge_of_slot;  // per triangle edge 3t + k: its edge, or kNoEdge
};

// Face normals only (the first step of both ways below), from each triangle's corners.
Buffer<Vec3> face_normals(std::span<const TriangleCorners> corners);

// On the halfedge structure built by halfedge_mesh from `incidence`.
Pseudonormals halfedge_pseudonormals(const TriMesh& mesh, const EdgeIncidence& incidence);

// On the arrays: `corners` are `mesh`'s triangles' corners, `incidence` its edge incidence
// (its edge_of_slot becomes the result's).
Pseudonormals array_pseudonormals(const Mesh& mesh, std::span<const TriangleCorners> corners,
                                  EdgeIncidence incidence);

}  // namespace ncv
