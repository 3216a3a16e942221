// The area-weighted error histogram as a self-contained SVG: one bar per bin, its height
// the bin's share of the area and its colour the map's at the bin centre, with axes,
// labels and the tolerance limits as dashed lines.
#pragma once

#include <optional>
#include <ostream>
#include <string_view>

#include "render/color_map.hpp"
#include "statistics/area_histogram.hpp"
#include "statistics/tolerance.hpp"

namespace ncv {

void write_histogram_svg(std::ostream& out, const Histogram& histogram, const ColorMap& map,
                         std::string_view units = "model units");

// Bars coloured as colorize would by default: the tolerance map over the histogram's
// range when there is a tolerance, else the diverging map over +-max |value|.
void write_histogram_svg(std::ostream& out, const Histogram& histogram,
                         const std::optional<Tolerance>& tolerance,
                         std::string_view units = "model units");

}  // namespace ncv
