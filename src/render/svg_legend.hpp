// The colour bar of a colour map as a self-contained SVG: the map's gradient over its
// range with tick values, the tolerance limits marked, and the colour of "no sample".
#pragma once

#include <ostream>
#include <string_view>

#include "render/color_map.hpp"

namespace ncv {

// units labels the values ("mm", "model units").
void write_legend_svg(std::ostream& out, const ColorMap& map, std::string_view units);

}  // namespace ncv
