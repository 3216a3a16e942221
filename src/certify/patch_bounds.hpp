// Bounds on the signed error over one lattice sub-triangle (a "patch"), from its three
// measured corners (docs/CERTIFICATION.md):
//  - |d| from above by convexity: the distance to one fixed reference triangle is convex, so
//    over the patch it is at most its largest value at the corners; the least such maximum
//    over the corners' closest triangles bounds |d| (it is the measured max |d| when the
//    corners share their closest triangle).
//  - the side from the 1-Lipschitz distance: a patch every point of which lies within h
//    of a corner (h the covering radius) whose corners are all farther than h from the
//    reference does not touch it, so its side cannot change inside; then |d| >= min |d_c| - h.
//  - and, for the few patches where that decides something, the side and |d| from below by
//    the least distance between the patch and the reference triangles near it
//    (triangle_distance.hpp), which is the exact least |d| up to the rounding slack.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <vector>

#include "geometry/bounding_box.hpp"
#include "geometry/closest_point.hpp"
#include "search/search_index.hpp"

namespace ncv {

struct PatchCorner {
  Vec3 point{0, 0, 0};     // in the reference's local frame
  double d = 0;            // signed distance to the reference, + outside it
  std::uint32_t face = 0;  // its closest reference triangle
};

struct Patch {
  std::array<PatchCorner, 3> corners;
  std::uint32_t triangle = 0;  // of the sampled mesh
  std::uint32_t depth = 0;     // 0 for a lattice sub-triangle, +1 per split
  bool near_checked = false;   // bounded by the nearby triangles (bound_by_nearby) already
  double radius = 0;  // covering_radius of the corners, set by bound_from_corners, which every
                      // patch refinement holds has been through
  // Proven: upper_abs >= |d| everywhere on the patch, and when side != 0, side * d >=
  // lower_abs everywhere: the error has that sign with |d| >= lower_abs, or, where the patch
  // touches the reference (lower_abs < 0), it crosses to the other side by -lower_abs at most.
  double upper_abs = 0;
  double lower_abs = 0;
  int side = 0;
  // Proven where the sign is the true side (1-Lipschitz d): low <= d <= high on the patch,
  // from the corners' values and the covering radius; unbounded otherwise.
  double high = std::numeric_limits<double>::infinity();
  double low = -std::numeric_limits<double>::infinity();

  double upper() const { return std::min(side < 0 ? -lower_abs : upper_abs, high); }
  double lower() const { return std::max(side > 0 ? lower_abs : -upper_abs, low); }
  Vec3 centre() const { return (corners[0].point + corners[1].point + corners[2].point) / 3.0; }
  TriangleCorners points() const { return {corners[0].point, corners[1].point, corners[2].point}; }
};

// A triangle shrunk towards its centre by `margin` at most (to its centre when smaller): every
// point of the triangle lies within `rim` of the shrunk one, which the coverings and the
// contact prism prove things of (docs/CERTIFICATION.md).
struct ShrunkTriangle {
  TriangleCorners corners;
  double radius = 0;  // the largest distance from the centre to a corner
  double rim = 0;
};
ShrunkTriangle shrink_towards_centre(const TriangleCorners& triangle, double margin);

// The contact prism for the width asked (docs/CERTIFICATION.md "The side at a contact"): over
// the patch shrunk by `margin`, from height `low` to `high`; where it proves a side,
// side * d >= `reached` on the patch.
struct ContactPrism {
  double margin = 0, low = 0, high = 0, reached = 0;
};
ContactPrism contact_prism(double width, double slack);

// Gives the patch the side a prism proved for a region holding it, unless a corner lies
// beyond what the proof allows (the surface would not be what the sign assumes).
void take_side(Patch& patch, int side, double reached);

// The largest distance from a point of triangle abc to the nearest of its corners: the
// circumradius when the triangle is acute; otherwise the larger distance from an end of the
// longest edge to where the perpendicular bisector of the edge between that end and the third
// corner meets it, at most half the longest edge (docs/CERTIFICATION.md "Bounds on one patch").
double covering_radius(Vec3 a, Vec3 b, Vec3 c);

// What refinement aims at: every patch's upper bound at most `upper` and its lower bound at
// least `lower` (the measured extremes widened by the width asked, `width`).
struct NearbyTargets {
  double upper = 0;
  double lower = 0;
  double width = 0;
};

// The cheap bounds from the corners alone (convexity, Lipschitz). `side_is_continuous`:
// the sign is the true side of a closed surface (pseudonormal), so it can only change where
// the patch touches the surface. With `targets`, the flat pairs (the costliest part of the
// convexity bound) are left out where |d| is already small enough to settle the patch.
void bound_from_corners(Patch& patch, MeshCorners reference, double slack, bool side_is_continuous,
                        const NearbyTargets* targets = nullptr);

// The reference triangles that can come within a distance of a patch, from the grid's cells.
class NearbyTriangles {
 public:
  explicit NearbyTriangles(const SearchIndex& index);
  MeshCorners triangles() const { return index_.triangles(); }
  // Calls visit(t) once for every triangle listed in a cell that meets the patch's box grown
  // by `reach` whose own box comes within `reach` of the patch's (a long sliver listed in
  // the cells but far from the patch is left out). When that grown box spans more than
  // `max_cells` cells: on a reference of at most `max_cells` triangles, every triangle whose
  // box (the same search_box) comes within `reach` instead (a few large faces, gridded
  // finely for the search: grid_builder.hpp), else none, returning false. visit returns
  // whether to go on: false (a caller whose cap is exceeded, for which the rest would change
  // nothing) stops the scan, which then returns false too.
  template <class Visit>
  bool for_each(const Patch& patch, double reach, std::uint64_t max_cells, Visit&& visit) {
    BoundingBox box;
    for (const PatchCorner& c : patch.corners) box.extend(c.point);
    return for_each(box, reach, max_cells, visit);
  }
  // The same around a box.
  template <class Visit>
  bool for_each(const BoundingBox& box, double reach, std::uint64_t max_cells, Visit&& visit);

 private:
  const SearchIndex& index_;
  std::vector<std::uint32_t> stamps_;
  std::uint32_t epoch_ = 0;
};

// Whether the shadows on the plane (unit normal n) of the reference triangles `cover` cover the
// triangle `shrunk`, which lies in that plane: a point of it lies strictly inside one of
// them and no edge of their union's outline comes within the slack of it
// (docs/CERTIFICATION.md "Covering triangles").
bool shadows_cover(MeshCorners reference, std::span<const std::uint32_t> cover, Vec3 n,
                   const TriangleCorners& shrunk, double slack);

// A point's signed distance to the reference, measured as a sample's is: the witness of the
// side of a prism no reference triangle meets.
using SideWitness = std::function<double(Vec3)>;

// The side of the reference the right prism over `shrunk` (a triangle with unit normal n)
// from height `low` to `high` lies on, on either side of its plane, when none of the `near`
// reference triangles meets it (all those within its reach must be among them): +1 outside,
// -1 inside, as a point of it measures; 0 when both prisms meet one (docs/CERTIFICATION.md
// "The side at a contact").
int free_prism_side(MeshCorners reference, std::span<const std::uint32_t> near,
                    const TriangleCorners& shrunk, Vec3 n, double low, double high,
                    const SideWitness& witness, double slack);

// The bounds from the reference triangles near the patch: proves the side where the patch
// does not touch the reference, raising lower_abs to the least patch-triangle distance, or
// where it touches the reference from one side only (a contact face or line), within a
// quarter of the width of the contact; then, while upper_abs still misses the targets,
// lowers it by single triangles and by triangles that cover the patch (which loses up to a
// quarter of the width). Leaves what it cannot scan as it is.
void bound_by_nearby(Patch& patch, NearbyTriangles& nearby, const SideWitness& witness,
                     const NearbyTargets& targets, double slack, bool side_is_continuous);

template <class Visit>
bool NearbyTriangles::for_each(const BoundingBox& box, double reach, std::uint64_t max_cells,
                               Visit&& visit) {
  const BackgroundGrid& grid = index_.grid();
  std::array<std::int64_t, 3> lo{}, hi{};
  std::uint64_t cells = 1;
  const std::span<const BoxBlock> boxes = index_.boxes();
  for (int axis = 0; axis < 3; ++axis) {
    // The grown box rounded outward, and the cells that meet it by the grid's own bounds: a
    // triangle within reach has a point in it, which lies in one of them, and the builder
    // lists a triangle in every cell it touches (a point on a shared face: in both).
    const double low = std::nextafter(box.min[axis] - reach, -INFINITY);
    const double high = std::nextafter(box.max[axis] + reach, INFINITY);
    if (!grid.cells_meeting(axis, low, high, lo[axis], hi[axis])) return true;  // off the grid
    cells *= static_cast<std::uint64_t>(hi[axis] - lo[axis] + 1);
  }
  if (cells > max_cells) {
    const MeshCorners triangles = index_.triangles();
    if (triangles.size() > max_cells) return false;
    for (std::uint32_t t = 0; t < triangles.size(); ++t) {
      if (box_gap(box, search_box(triangles[t])) <= reach && !visit(t)) return false;
    }
    return true;
  }
  if (++epoch_ == 0) {
    std::fill(stamps_.begin(), stamps_.end(), 0);
    epoch_ = 1;
  }
  for (std::int64_t k = lo[2]; k <= hi[2]; ++k) {
    for (std::int64_t j = lo[1]; j <= hi[1]; ++j) {
      for (std::int64_t i = lo[0]; i <= hi[0]; ++i) {
        const std::uint64_t cell =
            grid.cell_index(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j),
                            static_cast<std::uint32_t>(k));
        for (std::uint64_t e = grid.cell_offsets[cell]; e < grid.cell_offsets[cell + 1]; ++e) {
          const std::uint32_t t = grid.cell_triangles[e];
          if (stamps_[t] == epoch_) continue;
          stamps_[t] = epoch_;
          // The search's own box of this reference (float, rounded outward: it holds the
          // triangle, so its gap is never more than the triangle's).
          const BoxBlock& block = boxes[e / kBoxLanes];
          const std::size_t lane = e % kBoxLanes;
          BoundingBox triangle_box;
          triangle_box.min = Vec3(block.lo[0][lane], block.lo[1][lane], block.lo[2][lane]);
          triangle_box.max = Vec3(block.hi[0][lane], block.hi[1][lane], block.hi[2][lane]);
          if (box_gap(box, triangle_box) > reach) continue;
          if (!visit(t)) return false;
        }
      }
    }
  }
  return true;
}

}  // namespace ncv
