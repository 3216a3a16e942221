#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <sstream>
#include <string>
#include <vector>

#include "render/axis_ticks.hpp"
#include "render/color_map.hpp"
#include "render/svg_histogram.hpp"
#include "render/svg_legend.hpp"
#include "render/svg_text.hpp"

using ncv::ColorMap;
using ncv::ColorMapKind;
using ncv::Histogram;
using ncv::Tolerance;

namespace {

// Checks the XML structure: every element closed in order, attribute values and text free
// of raw '<' and of '&' that does not start an entity. Returns the element names met.
std::vector<std::string> check_well_formed(const std::string& xml) {
  std::vector<std::string> open, names;
  std::size_t at = 0;
  const auto check_text = [&](std::size_t from, std::size_t to) {
    for (std::size_t k = from; k < to; ++k) {
      if (xml[k] != '&') continue;
      const std::size_t semicolon = xml.find(';', k);
      REQUIRE(semicolon != std::string::npos);
      const std::string entity = xml.substr(k, semicolon - k + 1);
      CHECK((entity == "&amp;" || entity == "&lt;" || entity == "&gt;" || entity == "&quot;" ||
             entity == "&apos;"));
    }
  };
  while ((at = xml.find('<', at)) != std::string::npos) {
    if (xml.compare(at, 2, "<?") == 0) {
      at = xml.find("?>", at);
      REQUIRE(at != std::string::npos);
      continue;
    }
    const std::size_t end = xml.find('>', at);
    REQUIRE(end != std::string::npos);
    const std::string tag = xml.substr(at + 1, end - at - 1);
    REQUIRE(tag.find('<') == std::string::npos);
    check_text(at, end);
    if (tag[0] == '/') {
      REQUIRE_FALSE(open.empty());
      CHECK(open.back() == tag.substr(1));
      open.pop_back();
    } else {
      const std::string name = tag.substr(0, tag.find_first_of(" />"));
      names.push_back(name);
      if (tag.back() != '/') open.push_back(name);
    }
    const std::size_t next = xml.find('<', end);
    check_text(end + 1, next == std::string::npos ? xml.size() : next);
    at = end + 1;
  }
  CHECK(open.empty());
  REQUIRE_FALSE(names.empty());
  CHECK(names.front() == "svg");
  return names;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

std::size_t count_of(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
    ++count;
  }
  return count;
}

std::string legend(const ColorMap& map, std::string_view units = "mm") {
  std::ostringstream out;
  ncv::write_legend_svg(out, map, units);
  return out.str();
}

// Bins over [-0.2, 0.2] with areas 0, 1, 3, 2 and some area outside.
Histogram sample_histogram() {
  Histogram h;
  h.range = {-0.2, 0.2};
  h.area = {0, 1, 3, 2};
  h.below_range = 0.5;
  h.above_range = 0;
  h.total_area = 6.5;
  return h;
}

}  // namespace

TEST_CASE("axis ticks are round numbers that print short", "[svg]") {
  const auto labels = [](double lo, double hi, int wanted) {
    std::vector<std::string> out;
    for (double v : ncv::axis_ticks(lo, hi, wanted)) out.push_back(fmt::format("{}", v));
    return out;
  };
  CHECK(labels(0, 1, 5) == std::vector<std::string>{"0", "0.2", "0.4", "0.6", "0.8", "1"});
  CHECK(labels(-0.3, 0.3, 6) ==
        std::vector<std::string>{"-0.3", "-0.2", "-0.1", "0", "0.1", "0.2", "0.3"});
  CHECK(labels(-0.157, 0.221, 8) ==
        std::vector<std::string>{"-0.15", "-0.1", "-0.05", "0", "0.05", "0.1", "0.15", "0.2"});
  CHECK(labels(1200, 5100, 4) == std::vector<std::string>{"2000", "3000", "4000", "5000"});
  CHECK(labels(3e-7, 9e-7, 3) == std::vector<std::string>{"4e-07", "6e-07", "8e-07"});
  CHECK(ncv::axis_ticks(0.25, 0.25, 5) == std::vector<double>{0.25});
}

TEST_CASE("svg text helpers escape and format", "[svg]") {
  CHECK(ncv::xml_escaped("a<b & \"c\" > 'd'") == "a&lt;b &amp; &quot;c&quot; &gt; &apos;d&apos;");
  CHECK(ncv::hex_color({255, 0, 16}) == "#ff0010");
  CHECK(ncv::px(12.345678) == "12.35");
  CHECK(ncv::px(-0.001) == "0");
}

TEST_CASE("the legend is a colour bar with ticks, units and tolerance limits", "[svg]") {
  const ColorMap map =
      ncv::make_color_map(ColorMapKind::tolerance, {-0.3, 0.4}, Tolerance{-0.05, 0.1});
  const std::string svg = legend(map);
  const std::vector<std::string> names = check_well_formed(svg);
  CHECK(std::count(names.begin(), names.end(), "stop") == static_cast<long>(map.stops().size()));
  for (const char* tick :
       {">-0.3<", ">-0.2<", ">-0.1<", ">0<", ">0.1<", ">0.2<", ">0.3<", ">0.4<"}) {
    CHECK(contains(svg, tick));
  }
  CHECK(contains(svg, "upper 0.1<"));
  CHECK(contains(svg, "lower -0.05<"));
  CHECK(contains(svg, "(mm)"));
  CHECK(contains(svg, "no sample"));
  CHECK(contains(svg, ncv::hex_color(ncv::kNoValueColor)));
  // The gradient holds the map's colours.
  CHECK(contains(svg, ncv::hex_color(map.rgb(0))));
  CHECK(contains(svg, ncv::hex_color(map.rgb(0.4))));
}

TEST_CASE("legend labels are escaped and limits off the bar are named", "[svg]") {
  const ColorMap map =
      ncv::make_color_map(ColorMapKind::diverging, {-0.02, 0.03}, Tolerance{-0.05, 0.1});
  const std::string svg = legend(map, "<µm & co>");
  check_well_formed(svg);
  CHECK(contains(svg, "&lt;µm &amp; co&gt;"));
  CHECK(contains(svg, "upper 0.1 (above)"));
  CHECK(contains(svg, "lower -0.05 (below)"));
  SECTION("a degenerate range still draws") {
    const std::string flat =
        legend(ncv::make_color_map(ColorMapKind::turbo, {0.5, 0.5}, std::nullopt));
    check_well_formed(flat);
    CHECK(contains(flat, ">0.5<"));
  }
}

TEST_CASE("the histogram draws one coloured bar per non-empty bin", "[svg]") {
  const Histogram h = sample_histogram();
  const ColorMap map =
      ncv::make_color_map(ColorMapKind::diverging, {-0.2, 0.2}, Tolerance{-0.05, 0.1});
  std::ostringstream out;
  ncv::write_histogram_svg(out, h, map, "mm");
  const std::string svg = out.str();
  const std::vector<std::string> names = check_well_formed(svg);
  CHECK(count_of(svg, "% of the area</title></rect>") == 3);
  // Bin centres -0.05, 0.05, 0.15 give the bar colours.
  for (double centre : {-0.05, 0.05, 0.15}) CHECK(contains(svg, ncv::hex_color(map.rgb(centre))));
  CHECK(contains(svg, "lower -0.05<"));
  CHECK(contains(svg, "upper 0.1<"));
  CHECK(count_of(svg, "stroke-dasharray") == 2);
  for (const char* tick : {">-0.2<", ">-0.1<", ">0<", ">0.1<", ">0.2<"}) CHECK(contains(svg, tick));
  // Shares of the area: the largest bar is 3 / 6.5 = 46 %, so the axis reaches 50.
  CHECK(contains(svg, ">50<"));
  CHECK(contains(svg, "signed error (mm)"));
  CHECK(contains(svg, "share of area (%)"));
  CHECK(contains(svg, fmt::format("{} % below -0.2", 100 * 0.5 / 6.5)));
}

TEST_CASE("the default histogram colours follow the tolerance", "[svg]") {
  const Histogram h = sample_histogram();
  std::ostringstream with, without;
  ncv::write_histogram_svg(with, h, Tolerance{-0.05, 0.1});
  ncv::write_histogram_svg(without, h, std::nullopt);
  check_well_formed(with.str());
  check_well_formed(without.str());
  const ColorMap tolerance_map =
      ncv::make_color_map(ColorMapKind::tolerance, {-0.2, 0.2}, Tolerance{-0.05, 0.1});
  CHECK(contains(with.str(), ncv::hex_color(tolerance_map.rgb(0.05))));
  CHECK(contains(with.str(), ">upper 0.1<"));
  CHECK_FALSE(contains(without.str(), "upper"));
  CHECK(contains(without.str(), "model units"));
  SECTION("a single-value histogram and a far tolerance still draw") {
    Histogram flat;
    flat.range = {0.25, 0.25};
    flat.area = {4};
    flat.total_area = 4;
    std::ostringstream out;
    ncv::write_histogram_svg(out, flat, Tolerance{-5, 5});
    check_well_formed(out.str());
    CHECK(count_of(out.str(), "% of the area</title></rect>") == 1);
    CHECK(contains(out.str(), "upper 5 (off the plot)"));
  }
}
