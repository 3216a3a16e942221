// The nominal (CAD) mesh prepared for distance queries.
//
// Local frame: the mesh is translated so that its bounding-box centre is the origin. A part
// modelled 1,000,000 mm from the world origin then keeps all the digits of its small
// coordinates; queries are translated in (to_local).
// The translation is exact whenever query and part are within a factor two of each other
// in every coordinate (Sterbenz), which covers any sample near the part.
//
// Orientation: a nominal whose signed volume is negative beyond rounding (below -1e-9 of
// its bounding-box diagonal cubed) is taken as inward-oriented and all its triangles are
// flipped (corners 1 and 2 swapped) with a warning, so that "outside" keeps meaning excess
// material. Face indices are unchanged. This serves closed meshes (pseudonormals) and
// nearly closed ones (the winding number of an inward solid is -1 inside) alike; a flat
// sheet has no volume to speak of and is left as it is.
//
// Sign method (SignMethod::automatic): pseudonormals when the nominal is closed, manifold
// (edges and vertices), consistently oriented and encloses a volume (beyond the same
// tolerance); otherwise the generalized winding number, with a warning that says why.
//
// Pseudonormals (Baerentzen & Aanaes 2005) are built from unit face normals: a vertex sums
// the normals of its faces weighted by the face angle there, an edge sums the normals of
// the faces along it. Degenerate faces (see is_degenerate_triangle) have a zero normal and
// so contribute nothing; they cannot outvote their neighbours with a noisy direction.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geometry/closest_point.hpp"
#include "geometry/coordinate_limit.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_topology.hpp"
#include "reference/sign_method.hpp"
#include "util/buffer.hpp"

namespace ncv {

// Keeps slot indices (3 per triangle) and grid cell indices (<= 4 per triangle) in 32 bits.
inline constexpr std::size_t kMaxReferenceTriangles = std::size_t{1} << 28;

class ReferenceSurface {
 public:
  // Throws InputError(source, ...) for a mesh that cannot be used: no triangles, too many,
  // a vertex index out of range, a non-finite or absurdly large coordinate.
  ReferenceSurface(Mesh mesh, const std::string& source);

  std::size_t triangle_count() const { return corners_.size(); }
  Vec3 origin() const { return origin_; }
  Vec3 to_local(Vec3 global) const { return global - origin_; }

  const Mesh& local_mesh() const { return local_; }
  std::span<const TriangleCorners> corners() const { return corners_; }
  const TriangleCorners& corners(std::size_t triangle) const { return corners_[triangle]; }
  const BoundingBox& local_bounds() const { return local_bounds_; }

  // Topology of the mesh as given (before any flip).
  const TopologyReport& topology() const { return topology_; }
  bool flipped() const { return flipped_; }
  // SignMethod::pseudonormal or SignMethod::winding, and why when winding.
  SignMethod automatic_sign_method() const { return automatic_sign_; }
  const std::string& winding_reason() const { return winding_reason_; }

  // Unit normal, or zero for a degenerate face.
  Vec3 face_normal(std::size_t triangle) const { return face_normals_[triangle]; }
  // Unit pseudonormal of a feature of a triangle; zero when it has none (only degenerate
  // faces around it, or faces that cancel).
  Vec3 pseudonormal(std::size_t triangle, TriangleFeature feature) const;

 private:
  void orient_outward(const std::string& source);
  void choose_sign_method(const std::string& source);
  void copy_corners();
  void compute_normals(const EdgeIncidence& incidence);

  Vec3 origin_{0, 0, 0};
  Mesh local_;
  Buffer<TriangleCorners> corners_;
  BoundingBox local_bounds_;
  TopologyReport topology_;
  bool flipped_ = false;
  SignMethod automatic_sign_ = SignMethod::pseudonormal;
  std::string winding_reason_;
  Buffer<Vec3> face_normals_;
  std::vector<Vec3> vertex_normals_;
  std::vector<Vec3> edge_normals_;
  std::vector<std::uint32_t> edge_of_slot_;
};

}  // namespace ncv
