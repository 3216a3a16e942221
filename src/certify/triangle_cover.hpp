// Bounds shared by every patch of one sampled triangle, found once for all of them
// (docs/CERTIFICATION.md "One triangle at a time"): where a coarse triangle lies over a much
// finer reference (the reverse direction: a CAD face over a workpiece's scallops or strips),
// each of its patches would gather and test the same reference triangles again.
//  - The side: the prism proof (free_prism_side) over the whole triangle.
//  - |d| from above: the reference triangles within a cutoff of the triangle's plane whose
//    shadows cover it (shadows_cover), their heights kept in a map over the plane, so that a
//    patch is bounded by the greatest height of those whose shadow comes near its own.
//  - Where to measure: the points of the triangle straight below the covering triangles'
//    corners that stand farther from it than any of its corners (a crest of a scallop over
//    a flat face): the error there is likely beyond what the lattice measured.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "certify/patch_bounds.hpp"

namespace ncv {

struct TriangleCoverOptions {
  double cutoff = 0;  // the greatest height above or below the plane a covering triangle has
  double width = 0;   // the width asked: the margin and the prism's height derive from it
  double cell = 0;    // the height map's cell: about the triangle's lattice step
  double beyond = 0;  // where to measure: below corners of covering triangles farther than this
  std::size_t max_points = 0;
  std::uint64_t max_cells = 0;  // of the search grid the gathering may visit
  bool side_is_continuous = false;
  double slack = 0;
};

class TriangleCover {
 public:
  // Both proofs tried on the triangle; nullopt when its surroundings are too large to gather.
  static std::optional<TriangleCover> build(const TriangleCorners& triangle,
                                            NearbyTriangles& nearby, const SideWitness& witness,
                                            const TriangleCoverOptions& options);

  // The patch's bounds tightened by what the triangle proved (the patch lies in it).
  void bound(Patch& patch) const;

  // Points of the triangle worth measuring, in a fixed order.
  const std::vector<Vec3>& points_to_measure() const { return points_; }

 private:
  // A triangle's shadow on the map's plane: its extent along e1 (u) and e2 (v).
  struct Shadow {
    double u_low = INFINITY, u_high = -INFINITY, v_low = INFINITY, v_high = -INFINITY;
  };
  Shadow shadow(const TriangleCorners& points) const;
  // The map's cells the shadow, grown by `grow`, meets: columns i0..i1, rows j0..j1.
  struct Cells {
    std::size_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;
  };
  Cells cells_under(const Shadow& s, double grow) const;
  // The map's cells under the shadow grown by `grow` hold at least `height`.
  void raise(const Shadow& s, double grow, double height);

  // side * d >= side_reached on the whole triangle when side != 0.
  int side_ = 0;
  double side_reached_ = 0;
  // The height map, empty when the shadows do not cover the triangle.
  Vec3 origin_{0, 0, 0}, e1_{0, 0, 0}, e2_{0, 0, 0}, normal_{0, 0, 0};
  double u0_ = 0, v0_ = 0, cell_ = 0, rim_ = 0, slack_ = 0;
  std::size_t columns_ = 0, rows_ = 0;
  std::vector<double> highest_;  // per cell: the greatest |height| of a triangle over it
  std::vector<Vec3> points_;
};

}  // namespace ncv
