// The nominal part: an injection-mould core block, a height field z = h(x, y) over
// [0, 120] x [0, 80] mm so that 3-axis milling can make it. A base block carries a raised
// freeform core with drafted, filleted walls, a drafted cylindrical boss with a foot fillet,
// and a drafted rectangular pocket with sharp concave corners. The seed shapes the crown.
#pragma once

#include <cstdint>
#include <numbers>
#include <vector>

#include "ncgen/wall_profile.hpp"

namespace ncv::gen {

constexpr double degrees(double angle) {
  return angle * std::numbers::pi / 180;
}

struct FreeformCore {
  double center_x = 45;
  double center_y = 40;
  double half_x = 30;  // footprint: rounded rectangle along the walls' foot lines
  double half_y = 24;
  double corner_radius = 12;
  WallProfile wall{12, 24, degrees(7), 2, 1};
  // The crown rises over the plateau, blended in over crown_ramp from the plateau's edge:
  // wave * (1 + cos(2pi x'/wavelength_x + phase_x) cos(2pi y'/wavelength_y + phase_y)) / 2
  // plus a Gaussian bump.
  double crown_ramp = 8;
  double wave = 3;
  double wavelength_x = 40;
  double wavelength_y = 36;
  double phase_x = 0;
  double phase_y = 0;
  double bump = 2.5;
  double bump_x = 45;
  double bump_y = 40;
  double bump_sigma = 7;

  double height(double x, double y) const;  // wall.lower away from the core
};

struct Boss {
  double center_x = 100;
  double center_y = 58;
  double top_radius = 7;
  WallProfile wall{12, 26, degrees(5), 1.5, 0};

  double height(double x, double y) const;  // wall.lower away from the boss
};

// Rim and floor outlines are axis-parallel rectangles: with coordinates on grid lines every
// crease of the pocket is a grid line or a grid diagonal, and the tessellation is exact there.
struct Pocket {
  double min_x = 88.75;  // rim outline
  double min_y = 8.75;
  double max_x = 111.25;
  double max_y = 26.25;
  double wall_width = 0.625;  // horizontal run of the drafted walls
  double rim = 12;
  double floor = 5;

  // The pocket removes all material above this surface; infinite outside the rim.
  double ceiling(double x, double y) const;
};

struct MouldCore {
  double length = 120;
  double width = 80;
  double base = 12;
  FreeformCore core;
  Boss boss;
  Pocket pocket;

  double height(double x, double y) const;
  // Heights of the horizontal planar faces (base, pocket floor, boss top).
  std::vector<double> flat_levels() const;
};

MouldCore make_mould_core(std::uint64_t seed);

}  // namespace ncv::gen
