#include "ncgen/cutter.hpp"

#include <algorithm>
#include <cmath>

namespace ncv::gen {
namespace {

template <typename Profile>
Kernel sample_kernel(double radius, double spacing, const Profile& profile) {
  Kernel kernel;
  // A hair of slack so that samples exactly on the rim count despite rounding.
  const double rim = radius * (1 + 1e-12);
  kernel.reach = static_cast<int>(std::floor(rim / spacing));
  for (int dy = -kernel.reach; dy <= kernel.reach; ++dy) {
    const double y = dy * spacing;
    const int w =
        static_cast<int>(std::floor(std::sqrt(std::max(rim * rim - y * y, 0.0)) / spacing));
    std::vector<float>& row = kernel.rows.emplace_back();
    for (int dx = -w; dx <= w; ++dx) {
      row.push_back(static_cast<float>(profile(std::min(std::hypot(dx * spacing, y), radius))));
    }
    kernel.half_width.push_back(w);
  }
  return kernel;
}

}  // namespace

std::string_view shape_name(CutterShape shape) {
  return shape == CutterShape::flat_end ? "flat end" : "ball end";
}

double cutter_surface(const Cutter& cutter, double d) {
  if (cutter.shape == CutterShape::flat_end) return 0.0;
  return cutter.radius - std::sqrt(cutter.radius * cutter.radius - d * d);
}

double cutter_clearance(const Cutter& cutter, double allowance, double d) {
  if (cutter.shape == CutterShape::ball_end) {
    const double grown = cutter.radius + allowance;
    return std::sqrt(grown * grown - d * d) - cutter.radius;
  }
  // A flat end mill grown by a ball of radius `allowance`: flat disc, then a torus rim.
  if (d <= cutter.radius) return allowance;
  const double out = d - cutter.radius;
  return std::sqrt(allowance * allowance - out * out);
}

Kernel surface_kernel(const Cutter& cutter, double spacing) {
  return sample_kernel(cutter.radius, spacing, [&](double d) { return cutter_surface(cutter, d); });
}

Kernel clearance_kernel(const Cutter& cutter, double allowance, double spacing) {
  return sample_kernel(cutter.radius + allowance, spacing,
                       [&](double d) { return cutter_clearance(cutter, allowance, d); });
}

}  // namespace ncv::gen
