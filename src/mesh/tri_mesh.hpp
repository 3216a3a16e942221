// OpenMesh's halfedge triangle mesh in double precision, ncverify's mesh type for OpenMesh
// users (include/ncverify/verify.hpp), and the bridge between it and the plain arrays every
// algorithm reads (mesh.hpp). The array kernel keeps the points contiguous, so converting
// copies one array of points and one of corner indices.
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"

namespace ncv {

struct TriMeshTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};

using TriMesh = OpenMesh::TriMesh_ArrayKernelT<TriMeshTraits>;

// The mesh as arrays: vertex k is the TriMesh's vertex k, triangle t its face t, with the
// corners in the face's own order. Checked as a mesh file is (check_mesh), and a mesh with
// deleted elements not yet collected is refused (InputError naming `source`): its arrays
// would still hold the deleted vertices.
Mesh mesh_arrays(const TriMesh& mesh, const std::string& source);

// The arrays as a TriMesh, every triangle kept: a triangle OpenMesh's halfedge structure
// cannot hold where it is (a third face on an edge, a fan that would make a vertex
// non-manifold, a corner repeated) gets its own copies of its corners, as OpenMesh's file
// readers do. `copied_from` receives the array vertex each TriMesh vertex stands for.
TriMesh tri_mesh(const Mesh& mesh, std::vector<std::uint32_t>* copied_from = nullptr);

}  // namespace ncv
