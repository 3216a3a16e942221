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
// Topology and normals: a nominal OpenMesh can hold as it is (halfedge_mesh.hpp: at most two
// faces on an edge, in opposite directions, one fan per vertex) is held as an OpenMesh
// TriMesh, built once here (in the grid step) and let go once its results are taken: whether
// it is closed, its boundary loops, its face normals and its pseudonormals
// (pseudonormals.hpp) come from its halfedge structure. One it cannot hold is detected on the
// plain arrays (analyse_topology) and signed by the winding number; its pseudonormals (for an
// explicit --sign pseudonormal) come from the arrays. On the arrays, a surface whose fans can
// be walked (fans_walkable: the reverse direction's workpiece, as a rule) has each face normal
// and each vertex's or edge's pseudonormal worked out (around its fan) when asked
// (FanPseudonormals), the same values, rather than all up front. A grid file stores the results of
// a surface held on halfedges, so one read back (StoredSurface) rebuilds none of them.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geometry/closest_point.hpp"
#include "geometry/coordinate_limit.hpp"
#include "mesh/boundary_loops.hpp"
#include "mesh/mesh.hpp"
#include "mesh/mesh_corners.hpp"
#include "mesh/mesh_topology.hpp"
#include "reference/pseudonormals.hpp"
#include "reference/sign_method.hpp"
#include "util/buffer.hpp"

namespace ncv {

// Keeps slot indices (3 per triangle) and grid cell indices (<= 4 per triangle) in 32 bits.
inline constexpr std::size_t kMaxReferenceTriangles = std::size_t{1} << 28;

// Where the topology and pseudonormals come from. `run`'s reverse direction indexes the
// workpiece (1.25 M triangles in the paper-scale finishing job) on the arrays: there the
// halfedge way measured slower, run's reverse grid-build phase 1.22-1.41 s against
// 1.69-1.70 s (medians of 3, bench/compare_binaries.py, 2 busy cores), and its grid file
// 35 MB against 110 MB (the stored pseudonormals); the nominal's holes are what a report
// names, the workpiece's are not.
enum class SurfaceHolding { halfedges_where_possible, arrays };

// What a grid file keeps of a ReferenceSurface held on halfedges besides its mesh
// (docs/FORMATS.md).
struct StoredSurface {
  TopologyReport topology;
  bool flipped = false;
  std::uint64_t boundary_loop_count = 0;
  std::vector<BoundaryLoop> boundary_loops;  // the first of them (the file lists at most 100)
  std::vector<Vec3> vertex_pseudonormals;
  std::vector<Vec3> edge_pseudonormals;
  Buffer<std::uint32_t> edge_of_slot;
};

class ReferenceSurface {
 public:
  // Throws InputError(source, ...) for a mesh that cannot be used: no triangles, too many,
  // a vertex index out of range, a non-finite or absurdly large coordinate.
  // The surface keeps its own copy of `mesh`, in its local frame.
  ReferenceSurface(const Mesh& mesh, const std::string& source,
                   SurfaceHolding holding = SurfaceHolding::halfedges_where_possible);
  // From a grid file: `mesh` as read (before any flip) and what was computed from it on its
  // halfedges. The
  // face normals are made again from the corners (a per-face formula, the same bits), the
  // rest is taken as stored after checking its sizes and indices (InputError otherwise).
  ReferenceSurface(const Mesh& mesh, const std::string& source, StoredSurface stored);

  std::size_t triangle_count() const { return local_.triangle_count(); }
  Vec3 origin() const { return origin_; }
  Vec3 to_local(Vec3 global) const { return global - origin_; }

  // The triangles' corners in the local frame, after any flip.
  MeshCorners corners() const { return MeshCorners(local_); }
  TriangleCorners corners(std::size_t triangle) const { return corners()[triangle]; }
  const BoundingBox& local_bounds() const { return local_bounds_; }

  // Topology of the mesh as given (before any flip).
  const TopologyReport& topology() const { return topology_; }
  // True when the mesh was held as an OpenMesh TriMesh (see above).
  bool on_halfedges() const { return on_halfedges_; }
  // The boundary loops of an open surface held on halfedges, in model coordinates (read from
  // a grid file: the first 100 of them); their number.
  const std::vector<BoundaryLoop>& boundary_loops() const { return boundary_loops_; }
  std::uint64_t boundary_loop_count() const { return boundary_loop_count_; }
  // Empty when they come from the fans (fans_walkable); then ask the two below.
  const Pseudonormals& normals() const { return normals_; }
  bool flipped() const { return flipped_; }
  // SignMethod::pseudonormal or SignMethod::winding, and why when winding.
  SignMethod automatic_sign_method() const { return automatic_sign_; }
  const std::string& winding_reason() const { return winding_reason_; }

  // Unit normal, or zero for a degenerate face.
  Vec3 face_normal(std::size_t triangle) const {
    return fans_ ? FanPseudonormals::face(corners(), triangle) : normals_.face[triangle];
  }
  // Unit pseudonormal of a feature of a triangle; zero when it has none (only degenerate
  // faces around it, or faces that cancel). Inline: the distance step asks for one a sample.
  Vec3 pseudonormal(std::size_t triangle, TriangleFeature feature) const {
    if (is_vertex(feature)) {
      if (fans_) return fans_->vertex(local_, triangle, vertex_index(feature));
      return normals_.vertex[local_.triangles[triangle][vertex_index(feature)]];
    }
    if (is_edge(feature)) {
      if (fans_) return fans_->edge(corners(), triangle, edge_index(feature));
      const std::uint32_t edge = normals_.edge_of_slot[3 * triangle + edge_index(feature)];
      return edge == kNoEdge ? Vec3(0, 0, 0) : normals_.edge[edge];
    }
    return face_normal(triangle);
  }

 private:
  void enter_local_frame(const Mesh& mesh, const std::string& source);
  void orient_outward(const std::string& source);
  void choose_sign_method(const std::string& source);
  void compute_normals(EdgeIncidence& incidence, SurfaceHolding holding);

  Vec3 origin_{0, 0, 0};
  Mesh local_;
  BoundingBox local_bounds_;
  TopologyReport topology_;
  bool flipped_ = false;
  SignMethod automatic_sign_ = SignMethod::pseudonormal;
  std::string winding_reason_;
  bool on_halfedges_ = false;
  std::vector<BoundaryLoop> boundary_loops_;
  std::uint64_t boundary_loop_count_ = 0;
  // Empty when every normal comes from the fans (on the arrays, fans_walkable).
  Pseudonormals normals_;
  std::optional<FanPseudonormals> fans_;
};

}  // namespace ncv
