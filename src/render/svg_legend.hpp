// The colour bar of a colour map as a self-contained SVG: the map's gradient over its
// range with tick values, the tolerance limits marked, the part's name, the units and the
// colour of "no sample". With a tolerance map each of the three bands (gouge, within,
// excess) gets at least a readable share of the bar, however narrow its values: a gouge
// band 0.01 mm deep beside 0.8 mm of excess must not shrink to a hairline.
#pragma once

#include <ostream>

#include "render/color_map.hpp"
#include "render/svg_histogram.hpp"

namespace ncv {

void write_legend_svg(std::ostream& out, const ColorMap& map, const PictureText& text);

}  // namespace ncv
