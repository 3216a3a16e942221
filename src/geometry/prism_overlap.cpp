#include "geometry/prism_overlap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace ncv {
namespace {

// A point in the prism's frame: u, v along its base's plane, h along its normal.
struct Framed {
  double u = 0, v = 0, h = 0;
};

// A convex polygon of at most five corners: a triangle clipped by two parallel planes.
struct Polygon {
  std::array<Framed, 5> corners{};
  std::size_t size = 0;
};

// Keeps the part of the polygon with sign * (h - level) >= 0 (Sutherland-Hodgman).
Polygon clip(const Polygon& in, double level, double sign) {
  Polygon out;
  for (std::size_t k = 0; k < in.size; ++k) {
    const Framed& p = in.corners[k];
    const Framed& q = in.corners[(k + 1) % in.size];
    const double sp = sign * (p.h - level), sq = sign * (q.h - level);
    if (sp >= 0) out.corners[out.size++] = p;
    if ((sp >= 0) != (sq >= 0)) {
      const double t = sp / (sp - sq);
      out.corners[out.size++] = {p.u + t * (q.u - p.u), p.v + t * (q.v - p.v), level};
    }
  }
  return out;
}

// Whether the axis (nu, nv) separates the two point sets by more than slack.
bool separates(double nu, double nv, const Polygon& a, const Polygon& b, double slack) {
  const double length = std::hypot(nu, nv);
  if (!(length > 0)) return false;
  double a_low = INFINITY, a_high = -INFINITY, b_low = INFINITY, b_high = -INFINITY;
  for (std::size_t k = 0; k < a.size; ++k) {
    const double x = nu * a.corners[k].u + nv * a.corners[k].v;
    a_low = std::min(a_low, x);
    a_high = std::max(a_high, x);
  }
  for (std::size_t k = 0; k < b.size; ++k) {
    const double x = nu * b.corners[k].u + nv * b.corners[k].v;
    b_low = std::min(b_low, x);
    b_high = std::max(b_high, x);
  }
  return a_high + slack * length < b_low || b_high + slack * length < a_low;
}

// Some edge normal of either convex polygon separates them (the 2-D separating axis test).
bool any_edge_separates(const Polygon& a, const Polygon& b, double slack) {
  for (const Polygon* p : {&a, &b}) {
    for (std::size_t k = 0; k < p->size; ++k) {
      const Framed& s = p->corners[k];
      const Framed& e = p->corners[(k + 1) % p->size];
      if (separates(e.v - s.v, s.u - e.u, a, b, slack)) return true;
    }
  }
  return false;
}

}  // namespace

bool triangle_meets_prism(const TriangleCorners& triangle, const Prism& prism, double slack) {
  const Vec3 origin = prism.base[0];
  const Vec3 e1 = normalized(prism.base[1] - origin);
  const Vec3 e2 = cross(prism.normal, e1);
  const auto framed = [&](Vec3 p) {
    const Vec3 r = p - origin;
    return Framed{dot(r, e1), dot(r, e2), dot(r, prism.normal)};
  };
  Polygon part;
  for (const Vec3& p : triangle) part.corners[part.size++] = framed(p);
  part = clip(part, prism.low - slack, 1);
  if (part.size == 0) return false;
  part = clip(part, prism.high + slack, -1);
  if (part.size == 0) return false;
  Polygon base;
  for (const Vec3& p : prism.base) base.corners[base.size++] = framed(p);
  return !any_edge_separates(part, base, slack);
}

}  // namespace ncv
