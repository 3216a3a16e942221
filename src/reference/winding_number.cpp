#include "reference/winding_number.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/bounding_box.hpp"

namespace ncv {
namespace {

constexpr double kInverseFourPi = 0.25 / std::numbers::pi;

double solid_angle_from(Vec3 q, const TriangleCorners& t) {
  return solid_angle(t[0] - q, t[1] - q, t[2] - q);
}

Vec3 centroid(const TriangleCorners& t) {
  return (t[0] + t[1] + t[2]) / 3.0;
}
Vec3 area_vector_of(const TriangleCorners& t) {
  return 0.5 * cross(t[1] - t[0], t[2] - t[0]);
}

constexpr int kPairs[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};  // (j, k) -> symmetric slot

// g(d) = d / |d|^3 and its first two derivatives contracted with the node's moments.
double far_field(const Vec3& d, const Vec3& area_vector, const std::array<double, 9>& m,
                 const std::array<double, 18>& c) {
  const double d2 = squared_norm(d);
  const double inverse_d = 1.0 / std::sqrt(d2);
  const double inverse_d3 = inverse_d / d2;
  const double inverse_d5 = inverse_d3 / d2;
  const double inverse_d7 = inverse_d5 / d2;
  double dmd = 0, trace_terms = 0, cubic = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      dmd += d[i] * m[3 * i + j] * d[j];
      // sum_ik d_k C_iik twice (two of the three Kronecker terms) and sum_ij d_i C_ijj.
      trace_terms += 2 * d[j] * c[6 * i + kPairs[i][j]] + d[i] * c[6 * i + kPairs[j][j]];
      for (int k = 0; k < 3; ++k) cubic += d[i] * d[j] * d[k] * c[6 * i + kPairs[j][k]];
    }
  }
  const double zeroth = dot(area_vector, d) * inverse_d3;
  const double first = (m[0] + m[4] + m[8]) * inverse_d3 - 3 * dmd * inverse_d5;
  const double second = 0.5 * (-3 * trace_terms * inverse_d5 + 15 * cubic * inverse_d7);
  return zeroth + first + second;
}

}  // namespace

double solid_angle(Vec3 a, Vec3 b, Vec3 c) {
  const double la = norm(a);
  const double lb = norm(b);
  const double lc = norm(c);
  const double numerator = dot(a, cross(b, c));
  const double denominator = la * lb * lc + dot(a, b) * lc + dot(b, c) * la + dot(c, a) * lb;
  return 2.0 * std::atan2(numerator, denominator);
}

double winding_number_exact(MeshCorners triangles, Vec3 q) {
  double sum = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t) sum += solid_angle_from(q, triangles[t]);
  return sum * kInverseFourPi;
}

WindingNumberTree::WindingNumberTree(MeshCorners triangles) {
  std::vector<std::uint32_t> order(triangles.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  nodes_.reserve(2 * (triangles.size() / kLeafSize + 1));
  build(order, 0, static_cast<std::uint32_t>(order.size()), triangles);
  triangles_.reserve(triangles.size());
  for (std::uint32_t index : order) triangles_.push_back(triangles[index]);
}

WindingNumberTree::Node WindingNumberTree::summarise(std::span<const std::uint32_t> members,
                                                     MeshCorners triangles) {
  Node node;
  double area = 0;
  Vec3 weighted{0, 0, 0};
  BoundingBox box;
  for (std::uint32_t t : members) {
    const TriangleCorners corners = triangles[t];
    const double a = norm(area_vector_of(corners));
    area += a;
    weighted += a * centroid(corners);
    for (const Vec3& corner : corners) box.extend(corner);
  }
  node.centre = area > 0 ? weighted / area : box.center();
  for (std::uint32_t t : members) {
    const TriangleCorners corners = triangles[t];
    const Vec3 n = area_vector_of(corners);
    const Vec3 offset = centroid(corners) - node.centre;
    // int_t x x^T / |t| = (sum v v^T + s s^T) / 12 for corners v relative to p~, s their sum.
    const std::array<Vec3, 3> v = {corners[0] - node.centre, corners[1] - node.centre,
                                   corners[2] - node.centre};
    const Vec3 s = v[0] + v[1] + v[2];
    node.area_vector += n;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        node.moment[3 * i + j] += n[i] * offset[j];
        for (int k = j; k < 3; ++k) {
          const double xx = v[0][j] * v[0][k] + v[1][j] * v[1][k] + v[2][j] * v[2][k] + s[j] * s[k];
          node.second[6 * i + kPairs[j][k]] += n[i] * xx / 12.0;
        }
      }
    }
    for (const Vec3& corner : v) node.radius = std::max(node.radius, norm(corner));
  }
  return node;
}

// Median split of the centroids along the longest axis of their box; ties broken by index
// so the tree (and every evaluation order) is the same on every run.
std::uint32_t WindingNumberTree::build(std::vector<std::uint32_t>& order, std::uint32_t begin,
                                       std::uint32_t end, MeshCorners triangles) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  const std::span<std::uint32_t> members(order.data() + begin, end - begin);
  nodes_.push_back(summarise(members, triangles));
  nodes_[index].begin = begin;
  nodes_[index].end = end;
  if (end - begin <= kLeafSize) return index;

  BoundingBox centres;
  for (std::uint32_t t : members) centres.extend(centroid(triangles[t]));
  const Vec3 extent = centres.extent();
  const int axis =
      extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : (extent[1] >= extent[2] ? 1 : 2);
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(order.begin() + begin, order.begin() + middle, order.begin() + end,
                   [&](std::uint32_t a, std::uint32_t b) {
                     const double ca = centroid(triangles[a])[axis];
                     const double cb = centroid(triangles[b])[axis];
                     return ca != cb ? ca < cb : a < b;
                   });
  build(order, begin, middle, triangles);
  const std::uint32_t second = build(order, middle, end, triangles);
  nodes_[index].second_child = second;
  return index;
}

double WindingNumberTree::evaluate(Vec3 q) const {
  // Depth is at most log2(T / kLeafSize) + 2 for median splits, far below 64.
  std::array<std::uint32_t, 64> stack;
  std::size_t top = 0;
  stack[top++] = 0;
  double sum = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    const Vec3 d = node.centre - q;
    if (squared_norm(d) > kFarFieldRatio * kFarFieldRatio * node.radius * node.radius) {
      sum += far_field(d, node.area_vector, node.moment, node.second);
    } else if (node.second_child == 0) {
      for (std::uint32_t t = node.begin; t < node.end; ++t)
        sum += solid_angle_from(q, triangles_[t]);
    } else {
      stack[top++] = node.second_child;
      stack[top++] = static_cast<std::uint32_t>(&node - nodes_.data()) + 1;
    }
  }
  return sum * kInverseFourPi;
}

}  // namespace ncv
