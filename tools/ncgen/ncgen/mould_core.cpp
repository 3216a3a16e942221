#include "ncgen/mould_core.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ncgen/random.hpp"

namespace ncv::gen {
namespace {

// Signed distance to a rounded rectangle centred at the origin, negative inside.
double rounded_rectangle_distance(double x, double y, double half_x, double half_y, double radius) {
  const double qx = std::abs(x) - (half_x - radius);
  const double qy = std::abs(y) - (half_y - radius);
  return std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0) -
         radius;
}

// Quintic smoothstep: the crown joins the plateau with continuous slope and curvature.
double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * t * (t * (6 * t - 15) + 10);
}

}  // namespace

double FreeformCore::height(double x, double y) const {
  const double inward =
      -rounded_rectangle_distance(x - center_x, y - center_y, half_x, half_y, corner_radius);
  const double z = wall.height(inward);
  const double blend = smoothstep((inward - wall.head_end()) / crown_ramp);
  if (blend <= 0) return z;
  const double waves = std::cos(2 * std::numbers::pi * (x - center_x) / wavelength_x + phase_x) *
                       std::cos(2 * std::numbers::pi * (y - center_y) / wavelength_y + phase_y);
  const double r2 = (x - bump_x) * (x - bump_x) + (y - bump_y) * (y - bump_y);
  const double crown =
      wave * (1 + waves) / 2 + bump * std::exp(-r2 / (2 * bump_sigma * bump_sigma));
  return z + blend * crown;
}

double Boss::height(double x, double y) const {
  const double foot_radius = top_radius + (wall.upper - wall.lower) * std::tan(wall.draft);
  return wall.height(foot_radius - std::hypot(x - center_x, y - center_y));
}

double Pocket::ceiling(double x, double y) const {
  const double outside_floor = std::max({min_x + wall_width - x, x - max_x + wall_width,
                                         min_y + wall_width - y, y - max_y + wall_width, 0.0});
  if (outside_floor > wall_width) return std::numeric_limits<double>::infinity();
  return floor + outside_floor * (rim - floor) / wall_width;
}

double MouldCore::height(double x, double y) const {
  return std::min(std::max(core.height(x, y), boss.height(x, y)), pocket.ceiling(x, y));
}

std::vector<double> MouldCore::flat_levels() const {
  return {base, pocket.floor, boss.wall.upper};
}

MouldCore make_mould_core(std::uint64_t seed) {
  SplitMix64 random(seed);
  MouldCore part;
  FreeformCore& core = part.core;
  core.wave = random.uniform(2.5, 3.5);
  core.wavelength_x = random.uniform(34, 48);
  core.wavelength_y = random.uniform(30, 42);
  core.phase_x = random.uniform(0, 2 * std::numbers::pi);
  core.phase_y = random.uniform(0, 2 * std::numbers::pi);
  core.bump = random.uniform(2.0, 2.5);
  core.bump_x = core.center_x + random.uniform(-12, 12);
  core.bump_y = core.center_y + random.uniform(-8, 8);
  return part;
}

}  // namespace ncv::gen
