#include "render/svg_legend.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "render/axis_ticks.hpp"
#include "render/svg_text.hpp"

namespace ncv {

namespace {

// The tolerance limits are labelled left of the bar, the ticks right of it, so that
// neither hides the other.
constexpr double kWidth = 300, kHeight = 460;
constexpr double kBarLeft = 150, kBarWidth = 28;
constexpr double kMargin = 12;
constexpr double kBarTop = 56, kBarBottom = 376;
constexpr int kWantedTicks = 7;

struct BarScale {
  ValueRange range;

  // Values grow upwards; a degenerate range sits in the middle of the bar.
  double y(double value) const {
    if (range.hi == range.lo) return (kBarTop + kBarBottom) / 2;
    return kBarBottom - (value - range.lo) / (range.hi - range.lo) * (kBarBottom - kBarTop);
  }
  double offset(double value) const {
    return range.hi == range.lo ? 0 : (value - range.lo) / (range.hi - range.lo);
  }
};

void write_gradient(std::ostream& out, const ColorMap& map, const BarScale& scale) {
  out << "<defs><linearGradient id=\"ncv-bar\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">\n";
  for (const ColorStop& stop : map.stops()) {
    fmt::print(out, "<stop offset=\"{}\" stop-color=\"{}\"/>\n", scale.offset(stop.value),
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

void write_ticks(std::ostream& out, const ColorMap& map, const BarScale& scale) {
  const double right = kBarLeft + kBarWidth;
  for (const double value : axis_ticks(map.range.lo, map.range.hi, kWantedTicks)) {
    const double y = scale.y(value);
    fmt::print(out, "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#333\"/>\n", right,
               px(y), right + 6, px(y));
    fmt::print(out, "<text x=\"{}\" y=\"{}\" font-size=\"12\">{}</text>\n", right + 10, px(y + 4),
               value);
  }
}

// A limit outside the range is not on the bar; its label says so at the bar's end.
void write_limit(std::ostream& out, const ColorMap& map, const BarScale& scale,
                 std::string_view name, double limit) {
  const bool on_bar = limit >= map.range.lo && limit <= map.range.hi;
  const double y = on_bar ? scale.y(limit) : (limit > map.range.hi ? kBarTop : kBarBottom);
  if (on_bar) {
    fmt::print(out,
               "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"#000\" "
               "stroke-width=\"2\"/>\n",
               kBarLeft - 6, px(y), kBarLeft + kBarWidth, px(y));
  }
  fmt::print(out,
             "<text x=\"{}\" y=\"{}\" font-size=\"12\" font-weight=\"bold\" "
             "text-anchor=\"end\">{} {}{}</text>\n",
             kBarLeft - 10, px(y + 4), name, limit,
             on_bar ? "" : (limit > map.range.hi ? " (above)" : " (below)"));
}

void write_no_value(std::ostream& out) {
  const double top = kBarBottom + 22;
  fmt::print(out,
             "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"14\" fill=\"{}\" stroke=\"#333\" "
             "stroke-width=\"0.8\"/>\n",
             kBarLeft, top, kBarWidth, hex_color(kNoValueColor));
  fmt::print(out, "<text x=\"{}\" y=\"{}\" font-size=\"12\">no sample</text>\n",
             kBarLeft + kBarWidth + 10, top + 11);
}

}  // namespace

void write_legend_svg(std::ostream& out, const ColorMap& map, std::string_view units) {
  const BarScale scale{map.range};
  fmt::print(out,
             "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
             "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
             "viewBox=\"0 0 {0} {1}\" font-family=\"sans-serif\">\n",
             kWidth, kHeight);
  fmt::print(out, "<title>{}</title>\n", xml_escaped(map.description()));
  out << "<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  fmt::print(
      out,
      "<text x=\"{}\" y=\"22\" font-size=\"14\" font-weight=\"bold\">signed error ({})</text>\n",
      kMargin, xml_escaped(units));
  fmt::print(out,
             "<text x=\"{}\" y=\"40\" font-size=\"11\" fill=\"#555\">+ excess material, "
             "\u2212 gouge; map: {}</text>\n",
             kMargin, name_of(kColorMapNames, map.kind));
  write_gradient(out, map, scale);
  write_ticks(out, map, scale);
  if (map.tolerance) {
    write_limit(out, map, scale, "upper", map.tolerance->upper);
    write_limit(out, map, scale, "lower", map.tolerance->lower);
  }
  write_no_value(out);
  out << "</svg>\n";
}

}  // namespace ncv
