#include "geometry/triangle_distance.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ncv {
namespace {

// The gap between the projections of the two triangles on `axis`, as a length (the axis
// need not be unit); negative when they overlap along it, and for a zero axis.
double gap_along(Vec3 axis, const TriangleCorners& a, const TriangleCorners& b) {
  const double length = norm(axis);
  if (!(length > 0)) return -1;
  double a_lo = dot(axis, a[0]), a_hi = a_lo, b_lo = dot(axis, b[0]), b_hi = b_lo;
  for (int k = 1; k < 3; ++k) {
    const double pa = dot(axis, a[k]), pb = dot(axis, b[k]);
    a_lo = std::min(a_lo, pa);
    a_hi = std::max(a_hi, pa);
    b_lo = std::min(b_lo, pb);
    b_hi = std::max(b_hi, pb);
  }
  return std::max(b_lo - a_hi, a_lo - b_hi) / length;
}

std::array<Vec3, 3> edges(const TriangleCorners& t) {
  return {t[1] - t[0], t[2] - t[1], t[0] - t[2]};
}

}  // namespace

double segment_squared_distance(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2) {
  // Ericson 5.1.9: the closest points p1 + s d1 and p2 + t d2, clamped to the segments.
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = squared_norm(d1), e = squared_norm(d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (!(a > 0) && !(e > 0)) return squared_norm(r);
  if (!(a > 0)) {
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (!(e > 0)) {
      s = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2);
      const double denominator = a * e - b * b;
      s = denominator > 0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0, 1.0);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return squared_norm((p1 + s * d1) - (p2 + t * d2));
}

bool triangles_separated(const TriangleCorners& a, const TriangleCorners& b, double slack) {
  const std::array<Vec3, 3> ea = edges(a), eb = edges(b);
  const Vec3 na = cross(ea[0], ea[1]), nb = cross(eb[0], eb[1]);
  if (gap_along(na, a, b) > slack || gap_along(nb, a, b) > slack) return true;
  for (const Vec3& u : ea) {
    for (const Vec3& v : eb) {
      if (gap_along(cross(u, v), a, b) > slack) return true;
    }
  }
  // In-plane edge normals separate (nearly) coplanar triangles, where the cross products
  // all point along the shared normal; each triangle's edges are taken in either plane, so
  // that a degenerate one (a segment, with no normal of its own) is separated too.
  for (const Vec3& normal : {na, nb}) {
    for (const Vec3& u : ea) {
      if (gap_along(cross(normal, u), a, b) > slack) return true;
    }
    for (const Vec3& v : eb) {
      if (gap_along(cross(normal, v), a, b) > slack) return true;
    }
  }
  return false;
}

double triangle_distance_lower_bound(const TriangleCorners& a, const TriangleCorners& b,
                                     double slack) {
  if (!triangles_separated(a, b, slack)) return 0;
  double least = closest_point_on_triangle(a[0], b).squared_distance;
  for (int k = 0; k < 3; ++k) {
    least = std::min(least, closest_point_on_triangle(a[k], b).squared_distance);
    least = std::min(least, closest_point_on_triangle(b[k], a).squared_distance);
    for (int l = 0; l < 3; ++l) {
      least = std::min(least, segment_squared_distance(a[k], a[(k + 1) % 3], b[l], b[(l + 1) % 3]));
    }
  }
  return std::max(0.0, std::sqrt(least) - slack);
}

}  // namespace ncv
