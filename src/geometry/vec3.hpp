// The 3-vector of the whole core: OpenMesh's Vec3d, the point type of OpenMesh's meshes, so
// a point array of a TriMesh and a span of ncverify points are the same memory (zero-copy).
//
// Components are read as v[0], v[1], v[2]. OpenMesh's default constructor leaves the
// components unset, so a zero vector is written Vec3(0, 0, 0), never Vec3{}.
//
// The free functions below spell the arithmetic out component by component, in the order
// the kernels were proven and measured with (closest_point.hpp): OpenMesh's own dot (`|`)
// and cross (`%`) are templates over any dimension; these are what the hot loops inline.
#pragma once

#include <OpenMesh/Core/Geometry/VectorT.hh>
#include <algorithm>
#include <cmath>

namespace ncv {

using Vec3 = OpenMesh::Vec3d;

inline double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}
inline double squared_norm(const Vec3& a) {
  return dot(a, a);
}
inline double norm(const Vec3& a) {
  return std::sqrt(squared_norm(a));
}
inline Vec3 normalized(const Vec3& a) {
  const double length = norm(a);
  return length > 0 ? a / length : Vec3(0, 0, 0);
}
inline Vec3 component_min(const Vec3& a, const Vec3& b) {
  return Vec3(std::min(a[0], b[0]), std::min(a[1], b[1]), std::min(a[2], b[2]));
}
inline Vec3 component_max(const Vec3& a, const Vec3& b) {
  return Vec3(std::max(a[0], b[0]), std::max(a[1], b[1]), std::max(a[2], b[2]));
}
// The largest coordinate magnitude (the Chebyshev norm): how far from the origin a point's
// coordinates reach, the scale the search's margins and coordinate limits refer to.
inline double max_abs(const Vec3& a) {
  return std::max({std::fabs(a[0]), std::fabs(a[1]), std::fabs(a[2])});
}
inline bool is_finite(const Vec3& a) {
  return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
}

}  // namespace ncv
