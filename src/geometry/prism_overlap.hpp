// Whether a triangle meets a right prism: a base triangle swept along its plane's normal
// between two heights. The side proof at a contact (docs/CERTIFICATION.md "Contact") asks
// it of every reference triangle near a patch: a prism no reference triangle meets holds no
// point of the surface, so all of it lies on one side.
#pragma once

#include "geometry/closest_point.hpp"

namespace ncv {

struct Prism {
  TriangleCorners base;  // in a plane with unit normal `normal`
  Vec3 normal{0, 0, 1};
  double low = 0;  // the heights along `normal` it spans, low < high
  double high = 0;
};

// False only when the triangle stays more than `slack` (a length) away from the prism: below
// low, above high, or beside the base, seen along the normal. A triangle that may touch it
// meets it.
bool triangle_meets_prism(const TriangleCorners& triangle, const Prism& prism, double slack);

}  // namespace ncv
