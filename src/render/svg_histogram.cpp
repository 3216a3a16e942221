#include "render/svg_histogram.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "render/axis_ticks.hpp"
#include "render/svg_text.hpp"
#include "statistics/readable_numbers.hpp"

namespace ncv {

namespace {

constexpr double kWidth = 720, kHeight = 470;
constexpr double kLeft = 84, kRight = 690, kTop = 96, kBottom = 376;
constexpr double kMinBarWidth = 3;
constexpr double kMinBarHeight = 2;  // a bin below the axis floor still shows
constexpr int kMostDecades = 6;      // the log axis spans at most 1e-6 of the tallest bar
// Width of a character of a 12 px label, an upper estimate for sans-serif digits and
// letters, used to keep labels inside the picture and apart.
constexpr double kCharWidth = 7.4;

double percent_of(const Histogram& h, double area) {
  return h.total_area > 0 ? 100 * area / h.total_area : 0;
}

struct PlotScale {
  ValueRange x;         // values shown along the axis
  int low_decade = -1;  // the share axis runs from 10^low_decade %
  int high_decade = 2;  // to 10^high_decade %

  double px_x(double value) const {
    return kLeft + (value - x.lo) / (x.hi - x.lo) * (kRight - kLeft);
  }
  double px_y(double percent) const {
    const double decades = high_decade - low_decade;
    const double t = (std::log10(percent) - low_decade) / decades;
    return kBottom - std::clamp(t, 0.0, 1.0) * (kBottom - kTop);
  }
};

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

// The share axis runs over whole decades from the smallest non-empty bin to the tallest,
// at most kMostDecades of them.
PlotScale make_scale(const Histogram& h, const std::optional<Tolerance>& tolerance) {
  double largest = 0, smallest = 100;
  for (const double area : h.area) {
    const double percent = percent_of(h, area);
    if (!(percent > 0)) continue;
    largest = std::max(largest, percent);
    smallest = std::min(smallest, percent);
  }
  PlotScale scale{shown_range(h, tolerance)};
  if (largest > 0) {
    scale.high_decade = static_cast<int>(std::ceil(std::log10(largest)));
    const int low = static_cast<int>(std::floor(std::log10(smallest)));
    scale.low_decade = std::max(low, scale.high_decade - kMostDecades);
    if (scale.low_decade == scale.high_decade) --scale.low_decade;
  }
  return scale;
}

void write_bars(std::ostream& out, const Histogram& h, const ColorMap& map, const PlotScale& s,
                const PictureText& text) {
  for (std::size_t k = 0; k < h.bin_count(); ++k) {
    if (!(h.area[k] > 0)) continue;
    const double centre = (h.edge(k) + h.edge(k + 1)) / 2;
    double left = s.px_x(h.edge(k)), right = s.px_x(h.edge(k + 1));
    if (right - left < kMinBarWidth) {
      const double middle = (left + right) / 2;
      left = middle - kMinBarWidth / 2;
      right = middle + kMinBarWidth / 2;
    }
    const double percent = percent_of(h, h.area[k]);
    const double top = std::min(s.px_y(percent), kBottom - kMinBarHeight);
    fmt::print(out,
               "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" stroke=\"#333\" "
               "stroke-width=\"0.4\"><title>{} to {} {}: {:.3g} % of the area</title></rect>\n",
               px(left), px(top), px(right - left), px(kBottom - top), hex_color(map.rgb(centre)),
               fixed_or_zero(h.edge(k), text.decimals), fixed_or_zero(h.edge(k + 1), text.decimals),
               xml_escaped(text.units), percent);
  }
}

std::string decade_label(int decade) {
  return fmt::format("{}", std::pow(10.0, decade));
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
  for (int decade = s.low_decade; decade <= s.high_decade; ++decade) {
    const double y = s.px_y(std::pow(10.0, decade));
    fmt::print(out,
               "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#ddd\"/>\n"
               "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#000\"/>\n",
               kLeft, px(y), kRight, px(y), kLeft - 5, px(y), kLeft, px(y));
    fmt::print(out, "<text x=\"{}\" y=\"{}\" font-size=\"12\" text-anchor=\"end\">{}</text>\n",
               kLeft - 8, px(y + 4), decade_label(decade));
  }
  fmt::print(out,
             "<text x=\"{}\" y=\"{}\" font-size=\"13\" text-anchor=\"middle\">signed error ({}): "
             "+ excess material, \u2212 gouge</text>\n",
             (kLeft + kRight) / 2, kBottom + 40, xml_escaped(units));
  fmt::print(out,
             "<text transform=\"translate(20 {}) rotate(-90)\" font-size=\"13\" "
             "text-anchor=\"middle\">share of area (%, log scale)</text>\n",
             (kTop + kBottom) / 2);
}

// A label of the band above the plot: text anchored at x, on row 0 (next to the plot) or 1.
struct BandLabel {
  std::string text;
  double x;
  bool anchor_end;  // the text ends at x (else starts at x)
  int row;

  double left() const { return anchor_end ? x - width() : x; }
  double right() const { return anchor_end ? x : x + width(); }
  double width() const { return kCharWidth * static_cast<double>(text.size()); }
};

// Lower is labelled left of its line and upper right of it, so close limits keep their
// labels apart; a label that would leave the picture turns to the line's other side, and
// one that would then meet its neighbour moves to the row above.
std::vector<BandLabel> place_limit_labels(const Tolerance& zone, const PlotScale& s,
                                          std::string_view units) {
  std::vector<BandLabel> labels;
  for (const bool lower : {true, false}) {
    const double value = lower ? zone.lower : zone.upper;
    const char* name = lower ? "lower" : "upper";
    BandLabel label{fmt::format("{} {} {}", name, value, units), 0, lower, 0};
    if (value < s.x.lo || value > s.x.hi) {
      const bool low = value < s.x.lo;
      label.text += low ? " (off the plot, left)" : " (off the plot, right)";
      label.x = low ? kLeft : kRight;
      label.anchor_end = !low;
    } else {
      const double x = s.px_x(value);
      label.x = lower ? x - 4 : x + 4;
      if (label.left() < 4) label = {label.text, x + 4, false, 0};
      if (label.right() > kWidth - 4) label = {label.text, x - 4, true, 0};
    }
    labels.push_back(label);
  }
  if (labels[0].right() + 8 > labels[1].left()) labels[1].row = 1;
  return labels;
}

void write_limits(std::ostream& out, const Tolerance& zone, const PlotScale& s,
                  std::string_view units) {
  for (const double value : {zone.lower, zone.upper}) {
    if (value < s.x.lo || value > s.x.hi) continue;
    fmt::print(out,
               "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#000\" "
               "stroke-width=\"1.5\" stroke-dasharray=\"6,4\"/>\n",
               px(s.px_x(value)), kTop - 6, kBottom);
  }
  for (const BandLabel& label : place_limit_labels(zone, s, units)) {
    fmt::print(out,
               "<text x=\"{}\" y=\"{}\" font-size=\"12\" font-weight=\"bold\" "
               "text-anchor=\"{}\">{}</text>\n",
               px(label.x), kTop - 10 - 16 * label.row, label.anchor_end ? "end" : "start",
               xml_escaped(label.text));
  }
}

void write_outside_note(std::ostream& out, const Histogram& h, const PictureText& text) {
  if (!(h.below_range > 0) && !(h.above_range > 0)) return;
  fmt::print(out,
             "<text x=\"{}\" y=\"{}\" font-size=\"11\" fill=\"#555\">outside the histogram: {} % "
             "below {}, {} % above {}</text>\n",
             kLeft, kHeight - 12, fmt::format("{:.3g}", percent_of(h, h.below_range)),
             fixed_or_zero(h.range.lo, text.decimals),
             fmt::format("{:.3g}", percent_of(h, h.above_range)),
             fixed_or_zero(h.range.hi, text.decimals));
}

void write_title(std::ostream& out, const PictureText& text) {
  const std::string title = text.part.empty()
                                ? "Area-weighted histogram of the signed error"
                                : "Area-weighted histogram of the signed error: " + text.part;
  fmt::print(out, "<title>{}</title>\n", xml_escaped(title));
  out << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  fmt::print(out,
             "<text x=\"12\" y=\"24\" font-size=\"15\" font-weight=\"bold\">Area-weighted "
             "histogram of the signed error</text>\n");
  if (!text.part.empty()) {
    fmt::print(out, "<text x=\"12\" y=\"44\" font-size=\"13\" fill=\"#333\">{}</text>\n",
               xml_escaped(text.part));
  }
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

PictureText picture_text(const PartReport& report) {
  const NumberStyle numbers = report_number_style(report);
  return {report.part, numbers.units, numbers.length_decimals};
}

void write_histogram_svg(std::ostream& out, const Histogram& histogram, const ColorMap& map,
                         const PictureText& text) {
  const PlotScale scale = make_scale(histogram, map.tolerance);
  fmt::print(out,
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
             "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\">\n",
             kWidth, kHeight);
  write_title(out, text);
  write_bars(out, histogram, map, scale, text);
  write_axes(out, scale, text.units);
  if (map.tolerance) write_limits(out, *map.tolerance, scale, text.units);
  write_outside_note(out, histogram, text);
  out << "</svg>\n";
}

void write_histogram_svg(std::ostream& out, const Histogram& histogram,
                         const std::optional<Tolerance>& tolerance, const PictureText& text) {
  write_histogram_svg(out, histogram, default_map(histogram, tolerance), text);
}

}  // namespace ncv
