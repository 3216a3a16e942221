// Generalized winding number (Jacobson, Kavan, Sorkine-Hornung 2013): w(q) = sum of the
// signed solid angles of the triangles seen from q, over 4 pi. It is 1 inside and 0
// outside a closed outward surface and degrades gracefully for open, non-manifold or
// self-intersecting ones: the sign step calls q inside when w(q) >= 0.5.
//
// WindingNumberTree evaluates it fast (Barill, Dickson, Schmidt, Levin, Jacobson 2018,
// "Fast winding numbers for soups and clouds"): a bounding-volume hierarchy over the
// triangles stores, per node, the area-weighted centre p~, the radius r of a ball around p~
// that holds its triangles, and the moments of its area vectors a_t = |t| n_t about p~:
//   N = sum a_t,   M_ij = sum_t a_t,i int_t x_j / |t|,   C_ijk = sum_t a_t,i int_t x_j x_k / |t|
// (x relative to p~). The solid angle of a node is the integral of n . g over its triangles,
// g(x) = (x - q) / |x - q|^3; a node whose centre is farther than kFarFieldRatio * r from q
// contributes the Taylor expansion of g about p~ to second order,
//   Omega ~ g.N + Dg : M + 1/2 D2g : C,
// other nodes are opened, and leaves near q are summed exactly. The truncation error of a
// node falls like (r / |p~ - q|)^3 times its own solid angle; the tests bound the total
// against the exact O(T) sum.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/closest_point.hpp"
#include "mesh/mesh_corners.hpp"

namespace ncv {

// Signed solid angle of triangle (a, b, c) seen from the origin (Van Oosterom & Strackee):
// positive when the origin lies behind the triangle's counter-clockwise side.
double solid_angle(Vec3 a, Vec3 b, Vec3 c);

// The reference: every triangle's solid angle, summed in index order.
double winding_number_exact(MeshCorners triangles, Vec3 q);

class WindingNumberTree {
 public:
  static constexpr double kFarFieldRatio = 2.0;
  static constexpr std::uint32_t kLeafSize = 8;

  explicit WindingNumberTree(MeshCorners triangles);
  double evaluate(Vec3 q) const;

 private:
  struct Node {
    Vec3 centre{0, 0, 0};
    double radius = 0;
    Vec3 area_vector{0, 0, 0};
    std::array<double, 9> moment{};    // M, row-major
    std::array<double, 18> second{};   // C: per i, its symmetric (j, k) part 00 01 02 11 12 22
    std::uint32_t begin = 0, end = 0;  // range of triangles_ (leaves)
    std::uint32_t second_child = 0;    // 0 for a leaf; the first child follows the node
  };

  std::uint32_t build(std::vector<std::uint32_t>& order, std::uint32_t begin, std::uint32_t end,
                      MeshCorners triangles);
  static Node summarise(std::span<const std::uint32_t> members, MeshCorners triangles);

  std::vector<Node> nodes_;
  std::vector<TriangleCorners> triangles_;  // in leaf order
};

}  // namespace ncv
