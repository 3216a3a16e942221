// Small pieces of SVG text shared by the legend and the histogram.
#pragma once

#include <string>
#include <string_view>

#include "render/color_map.hpp"

namespace ncv {

// Text content or attribute value with &, <, >, " and ' escaped.
std::string xml_escaped(std::string_view text);
// "#rrggbb".
std::string hex_color(Rgb color);
// A drawing coordinate: rounded to 1/100 of a pixel, which no renderer resolves, and
// printed in the shortest form.
std::string px(double coordinate);

}  // namespace ncv
