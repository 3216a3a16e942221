// OpenMesh's halfedge structure of a mesh that it can hold as it is, built from the edge
// incidence in parallel rather than by add_face.
//
// OpenMesh can hold a mesh as it is when every edge has one or two triangles, two of them
// running along it in opposite directions, every vertex has a single fan of triangles, and
// no triangle repeats a corner; add_face refuses the rest (a third face on an edge, a
// second closed fan at a vertex, a flipped neighbour). These are counted on the plain
// arrays (analyse_topology), which detect such a mesh before any halfedge is made.
//
// Why not add_face: it is serial and, for a 1.24 M-face mesh, takes 0.40 s on one core,
// about the time of the whole nominal's grid step; every link it makes follows from the
// edge incidence, which is already built in parallel for the checks above. The result is
// the structure add_face builds (the tests compare them, and OpenMesh's own mesh checker
// accepts it), numbered for the arrays: vertex v is array vertex v, face t is triangle t,
// edge e is the incidence's edge e, and its halfedge 0 runs along the triangle edge with the
// lower slot (3t + k, see mesh_topology.hpp).
#pragma once

#include <cstdint>

#include "mesh/mesh.hpp"
#include "mesh/mesh_topology.hpp"
#include "mesh/tri_mesh.hpp"

namespace ncv {

// True when OpenMesh can hold `mesh` as it is (see above): `topology` from analyse_topology.
bool holds_as_halfedge_mesh(const Mesh& mesh, const TopologyReport& topology);

// The halfedge mesh of `mesh`, which holds_as_halfedge_mesh accepts; `incidence` is its
// edge incidence (build_edge_incidence).
TriMesh halfedge_mesh(const Mesh& mesh, const EdgeIncidence& incidence);

// The halfedge of triangle edge `slot` (3t + k, from corner k to corner k + 1) in the mesh
// halfedge_mesh builds.
TriMesh::HalfedgeHandle slot_halfedge(const EdgeIncidence& incidence, std::uint32_t slot);

}  // namespace ncv
