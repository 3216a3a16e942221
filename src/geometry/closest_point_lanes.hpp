// The exact closest point of one triangle to several points at once: closest_point.hpp's
// kernel with the points in the lanes of a vector (GCC's vector extensions: 2 lanes on SSE2,
// 4 on AVX2, 8 on AVX-512).
//
// Compiled once per instruction set: a translation unit includes this after its
// `#pragma GCC target` (search/group_search_avx2.cpp and its siblings), so the definitions
// take that target; GCC lowers 8-lane vectors to scalar code when the template is defined
// outside the target region, even if it is only ever inlined inside it (measured: 43 ns a
// point-triangle pair against 4.2). Everything here has internal linkage (static), so the
// copies of different translation units never stand in for each other.
//
// Each lane computes the scalar kernel's operations on its point, in the scalar kernel's
// order, none fused or reassociated (the project builds in ISO mode, where GCC contracts no
// a * b + c, and the lanes' targets are named without FMA): every region's condition and
// value is computed in every lane, and a lane takes the region the scalar kernel's branches
// would take, in their order. So a lane's squared distance, point and feature are the scalar
// kernel's to the bit (tests/unit/geometry/test_closest_point_lanes.cpp compares them on
// random, degenerate, collinear and far-from-the-origin cases). A lane that reaches the
// scalar kernel's degenerate path (no positive area where the face branch divides by it) is
// handed to the scalar kernel itself.
#pragma once

#include <cmath>
#include <cstdint>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "geometry/closest_point.hpp"

namespace ncv {

template <int kLanes>
struct LaneTypes {
  typedef double Real __attribute__((vector_size(8 * kLanes)));
  typedef std::int64_t Mask __attribute__((vector_size(8 * kLanes)));
};

// kLanes points, coordinate by coordinate.
template <int kLanes>
struct PointLanes {
  typename LaneTypes<kLanes>::Real x, y, z;
};

// The kernel's result per lane: squared distance, closest point, feature (its
// TriangleFeature value).
template <int kLanes>
struct TrianglePointLanes {
  typename LaneTypes<kLanes>::Real squared, x, y, z;
  typename LaneTypes<kLanes>::Mask feature;
};

// Whether any lane of a comparison's result is set (a movemask where the target has one).
template <int kLanes>
[[gnu::always_inline]] static inline bool any_lane(typename LaneTypes<kLanes>::Mask m) {
#if defined(__x86_64__)
  if constexpr (kLanes == 2) {
    return _mm_movemask_pd((__m128d)m) != 0;
  } else if constexpr (kLanes == 4) {
    return _mm256_movemask_pd((__m256d)m) != 0;
  } else {
    return _mm512_test_epi64_mask((__m512i)m, (__m512i)m) != 0;
  }
#else
  for (int k = 0; k < kLanes; ++k) {
    if (m[k] != 0) return true;
  }
  return false;
#endif
}

// Each lane's square root (correctly rounded, as std::sqrt).
template <int kLanes>
[[gnu::always_inline]] static inline typename LaneTypes<kLanes>::Real lane_sqrt(
    typename LaneTypes<kLanes>::Real v) {
  using Real = typename LaneTypes<kLanes>::Real;
#if defined(__x86_64__)
  if constexpr (kLanes == 2) {
    return (Real)_mm_sqrt_pd((__m128d)v);
  } else if constexpr (kLanes == 4) {
    return (Real)_mm256_sqrt_pd((__m256d)v);
  } else {
    // The masked form: GCC 12's _mm512_sqrt_pd reads an undefined vector it then warns of.
    return (Real)_mm512_mask_sqrt_pd((__m512d)v, static_cast<__mmask8>(0xFF), (__m512d)v);
  }
#else
  Real r;
  for (int k = 0; k < kLanes; ++k) r[k] = std::sqrt(v[k]);
  return r;
#endif
}

// A triangle's corners and edge vectors as the lanes read them: made once per triangle and
// read by every vector of points measured against it. Each edge is the scalar kernel's
// difference (b - a, c - a, c - b), component by component.
struct LaneTriangle {
  double a[3], b[3], c[3];
  double ab[3], ac[3], bc[3];
};

[[gnu::always_inline]] static inline LaneTriangle lane_triangle(const TriangleCorners& corners) {
  LaneTriangle t;
  for (int k = 0; k < 3; ++k) {
    t.a[k] = corners[0][k];
    t.b[k] = corners[1][k];
    t.c[k] = corners[2][k];
    t.ab[k] = t.b[k] - t.a[k];
    t.ac[k] = t.c[k] - t.a[k];
    t.bc[k] = t.c[k] - t.b[k];
  }
  return t;
}

template <int kLanes>
[[gnu::always_inline]] static inline TrianglePointLanes<kLanes> closest_point_on_triangle_lanes(
    const PointLanes<kLanes>& p, const LaneTriangle& tri) {
  using Real = typename LaneTypes<kLanes>::Real;
  using Mask = typename LaneTypes<kLanes>::Mask;
  const double* a = tri.a;
  const double* b = tri.b;
  const double* c = tri.c;
  const double* ab = tri.ab;
  const double* ac = tri.ac;
  const double* bc = tri.bc;
  const Real zero = Real{};

  const Real apx = p.x - a[0], apy = p.y - a[1], apz = p.z - a[2];
  const Real d1 = ab[0] * apx + ab[1] * apy + ab[2] * apz;
  const Real d2 = ac[0] * apx + ac[1] * apy + ac[2] * apz;
  const Real bpx = p.x - b[0], bpy = p.y - b[1], bpz = p.z - b[2];
  const Real d3 = ab[0] * bpx + ab[1] * bpy + ab[2] * bpz;
  const Real d4 = ac[0] * bpx + ac[1] * bpy + ac[2] * bpz;
  const Real vc = d1 * d4 - d3 * d2;
  const Real cpx = p.x - c[0], cpy = p.y - c[1], cpz = p.z - c[2];
  const Real d5 = ab[0] * cpx + ab[1] * cpy + ab[2] * cpz;
  const Real d6 = ac[0] * cpx + ac[1] * cpy + ac[2] * cpz;
  const Real vb = d5 * d2 - d1 * d6;
  const Real va = d3 * d6 - d5 * d4;
  const Real e1 = d4 - d3;
  const Real e2 = d5 - d6;
  const Real denominator = va + vb + vc;

  // Which region each lane takes: the first of the scalar kernel's tests that holds.
  const Mask vertex0 = (d1 <= 0.0) & (d2 <= 0.0);
  Mask rest = ~vertex0;
  const Mask vertex1 = rest & (d3 >= 0.0) & (d4 <= d3);
  rest &= ~vertex1;
  const Mask edge0 = rest & (vc <= 0.0) & (d1 >= 0.0) & (d3 <= 0.0) & (d1 - d3 > 0.0);
  rest &= ~edge0;
  const Mask vertex2 = rest & (d6 >= 0.0) & (d5 <= d6);
  rest &= ~vertex2;
  const Mask edge2 = rest & (vb <= 0.0) & (d2 >= 0.0) & (d6 <= 0.0) & (d2 - d6 > 0.0);
  rest &= ~edge2;
  const Mask edge1 = rest & (va <= 0.0) & (e1 >= 0.0) & (e2 >= 0.0) & (e1 + e2 > 0.0);
  rest &= ~edge1;
  // The scalar kernel leaves the face branch for !(denominator > 0) || !isfinite(...).
  const Mask degenerate = rest & ~((denominator > 0.0) & (denominator < __builtin_inf()));

  // An edge lane's point is start + t * along with the scalar kernel's operands for its
  // edge; a face lane's is (a + v * ab) + w * ac.
  const Real t = (edge0 ? d1 : edge2 ? d2 : e1) / (edge0 ? d1 - d3 : edge2 ? d2 - d6 : e1 + e2);
  const Real v = vb / denominator;
  const Real w = vc / denominator;
  const Mask on_edge = edge0 | edge1 | edge2;

  TrianglePointLanes<kLanes> out;
  Real point[3];
  for (int k = 0; k < 3; ++k) {
    const Real start = edge1 ? zero + b[k] : zero + a[k];
    const Real along = edge0 ? zero + ab[k] : edge2 ? zero + ac[k] : zero + bc[k];
    const Real face_point = (a[k] + v * ab[k]) + w * ac[k];
    Real x = on_edge ? start + t * along : face_point;
    x = vertex0 ? zero + a[k] : x;
    x = vertex1 ? zero + b[k] : x;
    x = vertex2 ? zero + c[k] : x;
    point[k] = x;
  }
  const Real dx = p.x - point[0], dy = p.y - point[1], dz = p.z - point[2];
  out.squared = dx * dx + dy * dy + dz * dz;
  out.x = point[0];
  out.y = point[1];
  out.z = point[2];
  const Mask none = Mask{};
  out.feature = vertex0   ? none + static_cast<std::int64_t>(TriangleFeature::vertex0)
                : vertex1 ? none + static_cast<std::int64_t>(TriangleFeature::vertex1)
                : vertex2 ? none + static_cast<std::int64_t>(TriangleFeature::vertex2)
                : edge0   ? none + static_cast<std::int64_t>(TriangleFeature::edge0)
                : edge1   ? none + static_cast<std::int64_t>(TriangleFeature::edge1)
                : edge2   ? none + static_cast<std::int64_t>(TriangleFeature::edge2)
                          : none + static_cast<std::int64_t>(TriangleFeature::face);

  if (any_lane<kLanes>(degenerate)) [[unlikely]] {
    for (int k = 0; k < kLanes; ++k) {
      if (degenerate[k] == 0) continue;
      const TrianglePoint scalar =
          detail::closest_on_degenerate(Vec3(p.x[k], p.y[k], p.z[k]), Vec3(a[0], a[1], a[2]),
                                        Vec3(b[0], b[1], b[2]), Vec3(c[0], c[1], c[2]));
      out.squared[k] = scalar.squared_distance;
      out.x[k] = scalar.point[0];
      out.y[k] = scalar.point[1];
      out.z[k] = scalar.point[2];
      out.feature[k] = static_cast<std::int64_t>(scalar.feature);
    }
  }
  return out;
}

}  // namespace ncv
