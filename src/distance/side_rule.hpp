// On which side of the reference surface a point lies (docs/METHOD.md "Signed distance"),
// given its closest hit: the one rule the distance step signs every sample with and
// certification signs the points it adds with, so both give the same value for a point.
//   pseudonormal  sign of (p - c) . n, n the pseudonormal of the feature c lies on. Where n
//                 is zero (a feature whose faces cancel or are all degenerate), the exact
//                 winding number decides; where only the product is zero, the point is on
//                 the surface up to rounding and counts as outside (+).
//   winding       inside when the generalized winding number w(p) >= 0.5 (fast hierarchy).
//   paper         the sample's own normal N_p: positive when N_p . (p - c) > 0.
#pragma once

#include <cmath>
#include <memory>

#include "reference/reference_surface.hpp"
#include "reference/sign_method.hpp"
#include "reference/winding_number.hpp"
#include "search/closest_point_search.hpp"

namespace ncv {

class SideRule {
 public:
  // `method` is resolved (never automatic); `surface` must outlive the rule.
  SideRule(const ReferenceSurface& surface, SignMethod method)
      : surface_(surface), method_(method) {
    if (method_ == SignMethod::winding)
      tree_ = std::make_unique<WindingNumberTree>(surface.corners());
  }

  SignMethod method() const { return method_; }

  // `p` in the surface's local frame; `normal` is read by SignMethod::paper only. A point
  // exactly on the surface gets +0.0 whatever the method.
  double signed_value(Vec3 p, const ClosestHit& hit, Vec3 normal) const {
    if (hit.squared_distance == 0) return 0.0;
    const double distance = std::sqrt(hit.squared_distance);
    return is_inside(p, hit, normal) ? -distance : distance;
  }

 private:
  bool is_inside(Vec3 p, const ClosestHit& hit, Vec3 normal) const {
    const Vec3 offset = p - hit.point;
    switch (method_) {
      case SignMethod::paper:
        return !(dot(normal, offset) > 0);
      case SignMethod::winding:
        return tree_->evaluate(p) >= 0.5;
      default: {  // pseudonormal
        const Vec3 pseudonormal = surface_.pseudonormal(hit.triangle, hit.feature);
        const double side = dot(offset, pseudonormal);
        if (side != 0) return side < 0;
        // With a usable pseudonormal, the offset of a point off the surface lies in the
        // feature's normal cone, where the dot product is strictly positive or negative;
        // a zero comes only from a point on the surface whose offset is rounding noise
        // (common: machined faces that coincide with nominal ones), so its sign is moot.
        if (pseudonormal != Vec3(0, 0, 0)) return false;
        return winding_number_exact(surface_.corners(), p) >= 0.5;
      }
    }
  }

  const ReferenceSurface& surface_;
  SignMethod method_;
  std::unique_ptr<WindingNumberTree> tree_;
};

}  // namespace ncv
