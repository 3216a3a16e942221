#include "render/svg_legend.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "render/axis_ticks.hpp"
#include "render/svg_text.hpp"
#include "statistics/readable_numbers.hpp"

namespace ncv {

namespace {

// The tolerance limits are labelled left of the bar, the ticks right of it, so that
// neither hides the other.
constexpr double kWidth = 320, kHeight = 480;
constexpr double kBarLeft = 160, kBarWidth = 28;
constexpr double kMargin = 12;
constexpr double kBarTop = 76, kBarBottom = 396;
constexpr double kMinBand = 48;       // px of bar every band of a tolerance map gets at least
constexpr double kLabelSpacing = 15;  // px between the baselines of two tick labels
constexpr int kWantedTicks = 7;

// Value to bar position: piecewise linear through knots (value, y), values growing upwards.
class BarScale {
 public:
  explicit BarScale(const ColorMap& map) {
    const ValueRange r = map.range;
    if (r.hi == r.lo) {
      knots_ = {{r.lo, (kBarTop + kBarBottom) / 2}};
      return;
    }
    std::vector<double> values{r.lo};
    if (map.kind == ColorMapKind::tolerance) {
      for (const double limit : {map.tolerance->lower, map.tolerance->upper}) {
        if (limit > values.back() && limit < r.hi) values.push_back(limit);
      }
    }
    values.push_back(r.hi);
    // Each band's height: its share of the range, but at least kMinBand, the rest shared
    // out in proportion to the values.
    const std::size_t bands = values.size() - 1;
    const double total = kBarBottom - kBarTop;
    const double spare = total - kMinBand * static_cast<double>(bands);
    double y = kBarBottom;
    knots_.push_back({values[0], y});
    for (std::size_t k = 0; k < bands; ++k) {
      const double share = (values[k + 1] - values[k]) / (r.hi - r.lo);
      y -= kMinBand + spare * share;
      knots_.push_back({values[k + 1], y});
    }
    knots_.back().second = kBarTop;
  }

  double y(double value) const {
    if (knots_.size() == 1) return knots_[0].second;
    for (std::size_t k = 1; k < knots_.size(); ++k) {
      if (value <= knots_[k].first || k + 1 == knots_.size()) {
        const auto [v0, y0] = knots_[k - 1];
        const auto [v1, y1] = knots_[k];
        return y0 + (y1 - y0) * (value - v0) / (v1 - v0);
      }
    }
    return kBarTop;
  }
  // Gradient offset: 0 at the bottom, 1 at the top.
  double offset(double value) const { return (kBarBottom - y(value)) / (kBarBottom - kBarTop); }

 private:
  std::vector<std::pair<double, double>> knots_;
};

void write_gradient(std::ostream& out, const ColorMap& map, const BarScale& scale) {
  out << "<defs><linearGradient id=\"ncv-bar\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">\n";
  for (const ColorStop& stop : map.stops()) {
    const double offset = map.range.hi == map.range.lo ? 0 : scale.offset(stop.value);
    fmt::print(out, "<stop offset=\"{}\" stop-color=\"{}\"/>\n", std::round(offset * 1e5) / 1e5,
               hex_color(stop.color));
  }
  out << "</linearGradient></defs>\n";
  const std::string fill = map.range.hi == map.range.lo ? hex_color(map.rgb(map.range.lo))
                                                        : std::string("url(#ncv-bar)");
  fmt::print(out,
             "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" stroke=\"#333\" "
             "stroke-width=\"0.8\"/>\n",
             kBarLeft, kBarTop, kBarWidth, kBarBottom - kBarTop, fill);
}

// Ticks from every band's own round numbers, each kept only where its label clears the
// labels already placed; the range's ends first, so the extremes are always named.
void write_ticks(std::ostream& out, const ColorMap& map, const BarScale& scale, int decimals) {
  // The ends are data (the worst errors), the rest round ticks.
  std::vector<double> candidates{map.range.lo, map.range.hi};
  std::vector<double> cuts{map.range.lo};
  if (map.kind == ColorMapKind::tolerance) {
    for (const double limit : {map.tolerance->lower, map.tolerance->upper}) {
      if (limit > map.range.lo && limit < map.range.hi) cuts.push_back(limit);
    }
  }
  cuts.push_back(map.range.hi);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double px_height = scale.y(cuts[k]) - scale.y(cuts[k + 1]);
    const int wanted =
        std::max(1, static_cast<int>(px_height / (kBarBottom - kBarTop) * kWantedTicks));
    for (const double v : axis_ticks(cuts[k], cuts[k + 1], wanted)) candidates.push_back(v);
  }
  std::vector<double> placed_y;
  const double right = kBarLeft + kBarWidth;
  for (const double value : candidates) {
    const double y = scale.y(value);
    const bool clear = std::all_of(placed_y.begin(), placed_y.end(), [&](double other) {
      return std::abs(other - y) >= kLabelSpacing;
    });
    if (!clear) continue;
    placed_y.push_back(y);
    fmt::print(out, "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#333\"/>\n", right,
               px(y), right + 6, px(y));
    const bool end = value == map.range.lo || value == map.range.hi;
    fmt::print(out, "<text x=\"{}\" y=\"{}\" font-size=\"12\">{}</text>\n", right + 10, px(y + 4),
               end ? fixed_or_zero(value, decimals) : fmt::format("{}", value));
  }
}

// A limit outside the range is not on the bar; its label says so at the bar's end.
// Labels of limits that would overlap move apart, the upper up, the lower down.
void write_limits(std::ostream& out, const ColorMap& map, const BarScale& scale) {
  const Tolerance zone = *map.tolerance;
  double label_y[2];
  const double limits[2] = {zone.lower, zone.upper};
  for (int k = 0; k < 2; ++k) {
    const double limit = limits[k];
    const bool on_bar = limit >= map.range.lo && limit <= map.range.hi;
    label_y[k] = on_bar ? scale.y(limit) : (limit > map.range.hi ? kBarTop : kBarBottom);
    if (on_bar) {
      fmt::print(out,
                 "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#000\" "
                 "stroke-width=\"2\"/>\n",
                 kBarLeft - 6, px(label_y[k]), kBarLeft + kBarWidth, px(label_y[k]));
    }
  }
  const double gap = label_y[0] - label_y[1];
  if (gap < kLabelSpacing) {
    const double middle = (label_y[0] + label_y[1]) / 2;
    label_y[0] = middle + kLabelSpacing / 2;
    label_y[1] = middle - kLabelSpacing / 2;
  }
  for (int k = 0; k < 2; ++k) {
    const double limit = limits[k];
    const bool on_bar = limit >= map.range.lo && limit <= map.range.hi;
    fmt::print(out,
               "<text x=\"{}\" y=\"{}\" font-size=\"12\" font-weight=\"bold\" "
               "text-anchor=\"end\">{} {}{}</text>\n",
               kBarLeft - 10, px(label_y[k] + 4), k == 0 ? "lower" : "upper", limit,
               on_bar ? "" : (limit > map.range.hi ? " (above)" : " (below)"));
  }
}

void write_no_value(std::ostream& out) {
  const double top = kBarBottom + 26;
  fmt::print(out,
             "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"14\" fill=\"{}\" stroke=\"#333\" "
             "stroke-width=\"0.8\"/>\n",
             kBarLeft, top, kBarWidth, hex_color(kNoValueColor));
  fmt::print(out, "<text x=\"{}\" y=\"{}\" font-size=\"12\">no sample</text>\n",
             kBarLeft + kBarWidth + 10, top + 11);
}

void write_heading(std::ostream& out, const ColorMap& map, const PictureText& text) {
  fmt::print(
      out,
      "<text x=\"{}\" y=\"22\" font-size=\"14\" font-weight=\"bold\">signed error ({})</text>\n",
      kMargin, xml_escaped(text.units));
  if (!text.part.empty()) {
    fmt::print(out, "<text x=\"{}\" y=\"40\" font-size=\"12\" fill=\"#333\">{}</text>\n", kMargin,
               xml_escaped(text.part));
  }
  fmt::print(out,
             "<text x=\"{}\" y=\"58\" font-size=\"11\" fill=\"#555\">+ excess material, "
             "\u2212 gouge; map: {}</text>\n",
             kMargin, name_of(kColorMapNames, map.kind));
}

}  // namespace

void write_legend_svg(std::ostream& out, const ColorMap& map, const PictureText& text) {
  const BarScale scale(map);
  fmt::print(out,
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
             "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\">\n",
             kWidth, kHeight);
  fmt::print(out, "<title>{}</title>\n", xml_escaped(map.description()));
  out << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  write_heading(out, map, text);
  write_gradient(out, map, scale);
  write_ticks(out, map, scale, text.decimals);
  if (map.tolerance) write_limits(out, map, scale);
  write_no_value(out);
  out << "</svg>\n";
}

}  // namespace ncv
