#include "render/svg_histogram.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "render/axis_ticks.hpp"
#include "render/svg_text.hpp"

namespace ncv {

namespace {

constexpr double kWidth = 680, kHeight = 430;
constexpr double kLeft = 80, kRight = 650, kTop = 50, kBottom = 350;
constexpr double kMinBarWidth = 3;

struct PlotScale {
  ValueRange x;  // values shown along the axis
  double y_top;  // share of area (%) at the top of the plot

  double px_x(double value) const {
    return kLeft + (value - x.lo) / (x.hi - x.lo) * (kRight - kLeft);
  }
  double px_y(double percent) const { return kBottom - percent / y_top * (kBottom - kTop); }
};

double percent_of(const Histogram& h, double area) {
  return h.total_area > 0 ? 100 * area / h.total_area : 0;
}

// The histogram's range, widened to take in tolerance limits that lie within one range
// width of it (farther ones would squash the bars; their labels name them instead), and
// padded when it is a single value.
ValueRange shown_range(const Histogram& h, const std::optional<Tolerance>& tolerance) {
  ValueRange shown = h.range;
  const double width = h.range.hi - h.range.lo;
  if (tolerance) {
    for (const double limit : {tolerance->lower, tolerance->upper}) {
      if (limit >= h.range.lo - width && limit <= h.range.hi + width) {
        shown.lo = std::min(shown.lo, limit);
        shown.hi = std::max(shown.hi, limit);
      }
    }
  }
  if (shown.hi == shown.lo) {
    const double pad = shown.lo == 0 ? 1 : std::abs(shown.lo) / 10;
    shown = {shown.lo - pad, shown.hi + pad};
  }
  return shown;
}

// The share axis ends at the first tick at or above the tallest bar.
PlotScale make_scale(const Histogram& h, const std::optional<Tolerance>& tolerance) {
  double largest = 0;
  for (const double area : h.area) largest = std::max(largest, percent_of(h, area));
  if (!(largest > 0)) largest = 1;
  const std::vector<double> ticks = axis_ticks(0, largest, 5);
  const double top = ticks.back() >= largest ? ticks.back() : ticks.back() + (ticks[1] - ticks[0]);
  return {shown_range(h, tolerance), top};
}

void write_bars(std::ostream& out, const Histogram& h, const ColorMap& map, const PlotScale& s) {
  for (std::size_t k = 0; k < h.bin_count(); ++k) {
    if (!(h.area[k] > 0)) continue;
    const double centre = (h.edge(k) + h.edge(k + 1)) / 2;
    double left = s.px_x(h.edge(k)), right = s.px_x(h.edge(k + 1));
    if (right - left < kMinBarWidth) {
      const double middle = (left + right) / 2;
      left = middle - kMinBarWidth / 2;
      right = middle + kMinBarWidth / 2;
    }
    const double top = s.px_y(percent_of(h, h.area[k]));
    fmt::print(out,
               "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" stroke=\"#333\" "
               "stroke-width=\"0.4\"><title>{} to {}: {} % of the area</title></rect>\n",
               px(left), px(top), px(right - left), px(kBottom - top), hex_color(map.rgb(centre)),
               h.edge(k), h.edge(k + 1), percent_of(h, h.area[k]));
  }
}

void write_axes(std::ostream& out, const PlotScale& s, std::string_view units) {
  fmt::print(out, "<path d=\"M{0} {1} V{2} H{3}\" fill=\"none\" stroke=\"#000\"/>\n", kLeft, kTop,
             kBottom, kRight);
  for (const double value : axis_ticks(s.x.lo, s.x.hi, 8)) {
    const double x = s.px_x(value);
    fmt::print(out, "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#000\"/>\n", px(x),
               kBottom, kBottom + 5);
    fmt::print(out, "<text x=\"{}\" y=\"{}\" font-size=\"12\" text-anchor=\"middle\">{}</text>\n",
               px(x), kBottom + 19, value);
  }
  for (const double percent : axis_ticks(0, s.y_top, 5)) {
    const double y = s.px_y(percent);
    fmt::print(out, "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#000\"/>\n", kLeft - 5,
               px(y), kLeft, px(y));
    fmt::print(out, "<text x=\"{}\" y=\"{}\" font-size=\"12\" text-anchor=\"end\">{}</text>\n",
               kLeft - 8, px(y + 4), percent);
  }
  fmt::print(out,
             "<text x=\"{}\" y=\"{}\" font-size=\"13\" text-anchor=\"middle\">signed error ({}): "
             "+ excess material, \u2212 gouge</text>\n",
             (kLeft + kRight) / 2, kBottom + 40, xml_escaped(units));
  fmt::print(out,
             "<text transform=\"translate(22 {}) rotate(-90)\" font-size=\"13\" "
             "text-anchor=\"middle\">share of area (%)</text>\n",
             (kTop + kBottom) / 2);
}

// Lower is labelled left of its line and upper right of its line, so close limits keep
// their labels apart; a limit off the plot is named in its corner.
struct Limit {
  const char* name;
  double value;
  bool left;
};

void write_limits(std::ostream& out, const Tolerance& zone, const PlotScale& s) {
  int off_plot = 0;
  for (const Limit& limit : {Limit{"lower", zone.lower, true}, Limit{"upper", zone.upper, false}}) {
    if (limit.value < s.x.lo || limit.value > s.x.hi) {
      const bool low = limit.value < s.x.lo;
      fmt::print(out,
                 "<text x=\"{}\" y=\"{}\" font-size=\"12\" font-weight=\"bold\" "
                 "text-anchor=\"{}\">{} {} (off the plot)</text>\n",
                 low ? kLeft + 6 : kRight - 6, kTop + 14 + 16 * off_plot++, low ? "start" : "end",
                 limit.name, limit.value);
      continue;
    }
    const double x = s.px_x(limit.value);
    fmt::print(out,
               "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#000\" "
               "stroke-width=\"1.5\" stroke-dasharray=\"6,4\"/>\n",
               px(x), kTop - 8, kBottom);
    fmt::print(out,
               "<text x=\"{}\" y=\"{}\" font-size=\"12\" font-weight=\"bold\" "
               "text-anchor=\"{}\">{} {}</text>\n",
               px(limit.left ? x - 4 : x + 4), kTop - 4, limit.left ? "end" : "start", limit.name,
               limit.value);
  }
}

void write_outside_note(std::ostream& out, const Histogram& h) {
  if (!(h.below_range > 0) && !(h.above_range > 0)) return;
  fmt::print(out,
             "<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#555\">outside the histogram: {} % "
             "below {}, {} % above {}</text>\n",
             kLeft, kHeight - 10, percent_of(h, h.below_range), h.range.lo,
             percent_of(h, h.above_range), h.range.hi);
}

ColorMap default_map(const Histogram& h, const std::optional<Tolerance>& tolerance) {
  if (tolerance) {
    return make_color_map(
        ColorMapKind::tolerance,
        {std::min(h.range.lo, tolerance->lower), std::max(h.range.hi, tolerance->upper)},
        tolerance);
  }
  const double reach = std::max({std::abs(h.range.lo), std::abs(h.range.hi), 1e-12});
  return make_color_map(ColorMapKind::diverging, {-reach, reach}, std::nullopt);
}

}  // namespace

void write_histogram_svg(std::ostream& out, const Histogram& histogram, const ColorMap& map,
                         std::string_view units) {
  const PlotScale scale = make_scale(histogram, map.tolerance);
  fmt::print(out,
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
             "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\">\n",
             kWidth, kHeight);
  out << "<title>Area-weighted histogram of the signed error</title>\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  fmt::print(out,
             "<text x=\"{}\" y=\"20\" font-size=\"15\" font-weight=\"bold\">Area-weighted "
             "histogram of the signed error</text>\n",
             kLeft);
  write_bars(out, histogram, map, scale);
  write_axes(out, scale, units);
  if (map.tolerance) write_limits(out, *map.tolerance, scale);
  write_outside_note(out, histogram);
  out << "</svg>\n";
}

void write_histogram_svg(std::ostream& out, const Histogram& histogram,
                         const std::optional<Tolerance>& tolerance, std::string_view units) {
  write_histogram_svg(out, histogram, default_map(histogram, tolerance), units);
}

}  // namespace ncv
