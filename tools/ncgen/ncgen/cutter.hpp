// Milling cutters and their radial profiles sampled on a Z-map grid.
#pragma once

#include <string_view>
#include <vector>

namespace ncv::gen {

enum class CutterShape { flat_end, ball_end };

struct Cutter {
  CutterShape shape = CutterShape::ball_end;
  double radius = 1.0;
};

std::string_view shape_name(CutterShape shape);

// Height of the cutting surface above the tool tip at distance d <= radius from the axis.
double cutter_surface(const Cutter& cutter, double d);

// How high above a surface point at horizontal distance d the tip must stay for the cutter to
// keep `allowance` away from it along the normal (the cutter grown by the allowance touches
// the point). Defined for d <= radius + allowance.
double cutter_clearance(const Cutter& cutter, double allowance, double d);

// A radial function sampled at the grid offsets within `reach` of the tool axis: row dy
// (-reach..reach cells) holds the values for dx = -half_width..half_width.
struct Kernel {
  int reach = 0;
  std::vector<int> half_width;           // by dy + reach
  std::vector<std::vector<float>> rows;  // by dy + reach, then dx + half_width
};

Kernel surface_kernel(const Cutter& cutter, double spacing);
Kernel clearance_kernel(const Cutter& cutter, double allowance, double spacing);

}  // namespace ncv::gen
