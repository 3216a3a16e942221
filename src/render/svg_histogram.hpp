// The area-weighted error histogram as a self-contained SVG: one bar per bin, its height
// the bin's share of the area on a logarithmic scale (so that the out-of-tolerance tails,
// often a thousandth of the area, stay visible beside the bulk) and its colour the map's
// at the bin centre, with axes, the part's name, the units and the tolerance limits as
// dashed lines whose labels never overlap each other, the axes or the picture's edge.
#pragma once

#include <optional>
#include <ostream>
#include <string>

#include "render/color_map.hpp"
#include "statistics/area_histogram.hpp"
#include "statistics/statistics_report.hpp"
#include "statistics/tolerance.hpp"

namespace ncv {

// What a picture says besides its data.
struct PictureText {
  std::string part;  // the part's name, in the title; empty: none
  std::string units = "mm";
  int decimals = 4;  // of values that are data, not round ticks (statistics/readable_numbers.hpp)
};

// The part's name, units and decimals of a report.
PictureText picture_text(const PartReport& report);

void write_histogram_svg(std::ostream& out, const Histogram& histogram, const ColorMap& map,
                         const PictureText& text);

// Bars coloured as colorize would by default: the tolerance map over the histogram's
// range when there is a tolerance, else the diverging map over +-max |value|.
void write_histogram_svg(std::ostream& out, const Histogram& histogram,
                         const std::optional<Tolerance>& tolerance, const PictureText& text);

}  // namespace ncv
