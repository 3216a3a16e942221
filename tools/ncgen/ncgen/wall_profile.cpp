#include "ncgen/wall_profile.hpp"

#include <cmath>
#include <numbers>

namespace ncv::gen {
namespace {

// A fillet of radius r between the wall and a plane touches both at r * tan(alpha / 2) from
// their intersection, alpha being the wall's slope angle.
double tangent_length(double radius, double slope_angle) {
  return radius * std::tan(slope_angle / 2);
}

}  // namespace

double WallProfile::height(double u) const {
  const double alpha = std::numbers::pi / 2 - draft;
  const double slope = std::tan(alpha);
  const double top = (upper - lower) / slope;  // where the unfilleted wall meets `upper`
  const double foot = tangent_length(foot_fillet, alpha);
  const double head = tangent_length(head_fillet, alpha);
  if (u <= -foot) return lower;
  if (u < foot * std::cos(alpha)) {
    const double d = u + foot;
    return lower + foot_fillet - std::sqrt(foot_fillet * foot_fillet - d * d);
  }
  if (u <= top - head * std::cos(alpha)) return lower + slope * u;
  if (u < top + head) {
    const double d = u - top - head;
    return upper - head_fillet + std::sqrt(head_fillet * head_fillet - d * d);
  }
  return upper;
}

double WallProfile::head_end() const {
  const double alpha = std::numbers::pi / 2 - draft;
  return (upper - lower) / std::tan(alpha) + tangent_length(head_fillet, alpha);
}

}  // namespace ncv::gen
