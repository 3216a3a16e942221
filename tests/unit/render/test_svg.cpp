#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <array>
#include <cmath>
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

std::string legend(const ColorMap& map, std::string units = "mm") {
  std::ostringstream out;
  ncv::write_legend_svg(out, map, ncv::PictureText{"part_7", units});
  return out.str();
}

// A number attribute of an element's opening tag, e.g. attribute(tag, "y").
double attribute(const std::string& tag, const std::string& name) {
  const std::size_t at = tag.find(" " + name + "=\"");
  REQUIRE(at != std::string::npos);
  return std::stod(tag.substr(at + name.size() + 3));
}

// Every <text> element: its opening tag and its content.
std::vector<std::pair<std::string, std::string>> texts(const std::string& svg) {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t at = svg.find("<text "); at != std::string::npos;
       at = svg.find("<text ", at + 1)) {
    const std::size_t close = svg.find('>', at);
    const std::size_t end = svg.find("</text>", close);
    out.push_back({svg.substr(at, close - at), svg.substr(close + 1, end - close - 1)});
  }
  return out;
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
  // The ends at the part's resolution, round ticks between.
  for (const char* tick : {">-0.3000<", ">-0.2<", ">0<", ">0.2<", ">0.4000<"}) {
    CHECK(contains(svg, tick));
  }
  CHECK(contains(svg, "upper 0.1<"));
  CHECK(contains(svg, "lower -0.05<"));
  CHECK(contains(svg, "(mm)"));
  CHECK(contains(svg, ">part_7<"));
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
    CHECK(contains(flat, ">0.5000<"));
  }
}

TEST_CASE("the histogram draws one coloured bar per non-empty bin", "[svg]") {
  const Histogram h = sample_histogram();
  const ColorMap map =
      ncv::make_color_map(ColorMapKind::diverging, {-0.2, 0.2}, Tolerance{-0.05, 0.1});
  std::ostringstream out;
  ncv::write_histogram_svg(out, h, map, ncv::PictureText{"part_7", "mm"});
  const std::string svg = out.str();
  const std::vector<std::string> names = check_well_formed(svg);
  CHECK(count_of(svg, "% of the area</title></rect>") == 3);
  // Bin centres -0.05, 0.05, 0.15 give the bar colours.
  for (double centre : {-0.05, 0.05, 0.15}) CHECK(contains(svg, ncv::hex_color(map.rgb(centre))));
  CHECK(contains(svg, "lower -0.05 mm<"));
  CHECK(contains(svg, "upper 0.1 mm<"));
  CHECK(count_of(svg, "stroke-dasharray") == 2);
  for (const char* tick : {">-0.2<", ">-0.1<", ">0<", ">0.1<", ">0.2<"}) CHECK(contains(svg, tick));
  // Shares of the area on a log scale: the largest bar is 3 / 6.5 = 46 %, the smallest
  // 1 / 6.5 = 15 %, so the axis runs over the decades from 10 to 100.
  CHECK(contains(svg, ">10<"));
  CHECK(contains(svg, ">100<"));
  CHECK(contains(svg, "signed error (mm)"));
  CHECK(contains(svg, "share of area (%, log scale)"));
  CHECK(contains(svg, ">part_7<"));
  CHECK(contains(svg, "7.69 % below -0.2000"));
}

TEST_CASE("the default histogram colours follow the tolerance", "[svg]") {
  const Histogram h = sample_histogram();
  std::ostringstream with, without;
  ncv::write_histogram_svg(with, h, Tolerance{-0.05, 0.1}, {});
  ncv::write_histogram_svg(without, h, std::nullopt, {"", "model units"});
  check_well_formed(with.str());
  check_well_formed(without.str());
  const ColorMap tolerance_map =
      ncv::make_color_map(ColorMapKind::tolerance, {-0.2, 0.2}, Tolerance{-0.05, 0.1});
  CHECK(contains(with.str(), ncv::hex_color(tolerance_map.rgb(0.05))));
  CHECK(contains(with.str(), ">upper 0.1 mm<"));
  CHECK_FALSE(contains(without.str(), "upper"));
  CHECK(contains(without.str(), "model units"));
  SECTION("a single-value histogram and a far tolerance still draw") {
    Histogram flat;
    flat.range = {0.25, 0.25};
    flat.area = {4};
    flat.total_area = 4;
    std::ostringstream out;
    ncv::write_histogram_svg(out, flat, Tolerance{-5, 5}, {});
    check_well_formed(out.str());
    CHECK(count_of(out.str(), "% of the area</title></rect>") == 1);
    CHECK(contains(out.str(), "upper 5 mm (off the plot, right)"));
  }
}

TEST_CASE("every band of the tolerance legend is tall enough to see", "[svg]") {
  // A gouge band 0.01 deep beside 0.75 of excess: linear, it would be 4 px of 320.
  const ColorMap map =
      ncv::make_color_map(ColorMapKind::tolerance, {-0.16, 0.9}, Tolerance{-0.15, 0.15});
  const std::string svg = legend(map);
  std::vector<double> offsets;
  for (std::size_t at = svg.find("<stop "); at != std::string::npos;
       at = svg.find("<stop ", at + 1)) {
    offsets.push_back(attribute(svg.substr(at, svg.find('>', at) - at), "offset"));
  }
  // Stops: lo, lower (gouge side), lower (within), upper (within), upper (excess), hi.
  REQUIRE(offsets.size() == 6);
  const double bar = 320;  // px
  CHECK((offsets[1] - offsets[0]) * bar >= 40);
  CHECK((offsets[3] - offsets[2]) * bar >= 40);
  CHECK((offsets[5] - offsets[4]) * bar >= 40);
  // The ends are the data's, at the part's resolution, not 17 digits.
  CHECK(contains(svg, ">-0.1600<"));
  CHECK(contains(svg, ">0.9000<"));
}

TEST_CASE("legend labels keep apart however close the values", "[svg]") {
  const ColorMap map =
      ncv::make_color_map(ColorMapKind::tolerance, {-1, 1}, Tolerance{-0.001, 0.001});
  const std::string svg = legend(map);
  std::vector<double> left, right;  // baselines of labels left and right of the bar
  for (const auto& [tag, content] : texts(svg)) {
    if (attribute(tag, "y") < 70 || content == "no sample") continue;
    (contains(tag, "text-anchor=\"end\"") ? left : right).push_back(attribute(tag, "y"));
  }
  CHECK(left.size() == 2);
  CHECK(right.size() >= 3);
  for (const std::vector<double>* side : {&left, &right}) {
    for (std::size_t a = 0; a < side->size(); ++a) {
      for (std::size_t b = a + 1; b < side->size(); ++b) {
        CHECK(std::abs((*side)[a] - (*side)[b]) >= 14);
      }
    }
  }
}

TEST_CASE("histogram limit labels stay inside the picture and apart", "[svg]") {
  Histogram h = sample_histogram();
  const double width = 720;
  const double char_width = 7.4;
  for (const Tolerance zone : {Tolerance{-0.2, 0.2}, Tolerance{-0.01, 0.01}, Tolerance{0.19, 0.2},
                               Tolerance{-0.2, -0.199}, Tolerance{-9, 9}}) {
    std::ostringstream out;
    ncv::write_histogram_svg(out, h, zone, {"p", "mm"});
    const std::string svg = out.str();
    check_well_formed(svg);
    std::vector<std::array<double, 3>> boxes;  // left, right, baseline
    for (const auto& [tag, content] : texts(svg)) {
      if (content.rfind("lower", 0) != 0 && content.rfind("upper", 0) != 0) continue;
      const double x = attribute(tag, "x");
      const double w = char_width * static_cast<double>(content.size());
      const bool end = contains(tag, "text-anchor=\"end\"");
      boxes.push_back({end ? x - w : x, end ? x : x + w, attribute(tag, "y")});
    }
    REQUIRE(boxes.size() == 2);
    for (const auto& box : boxes) {
      CHECK(box[0] >= 0);
      CHECK(box[1] <= width);
      CHECK(box[2] < 96);  // above the plot, clear of the axes and bars
    }
    const bool same_row = boxes[0][2] == boxes[1][2];
    if (same_row) CHECK((boxes[0][1] <= boxes[1][0] || boxes[1][1] <= boxes[0][0]));
  }
}

TEST_CASE("the histogram's log scale keeps a tiny tail visible", "[svg]") {
  Histogram h;
  h.range = {-1, 1};
  h.area = {1e-5, 0, 0, 100};  // a thousandth of a percent in the gouge tail
  h.total_area = 100.00001;
  std::ostringstream out;
  ncv::write_histogram_svg(out, h, Tolerance{-0.5, 0.5}, {"p", "mm"});
  const std::string svg = out.str();
  std::vector<double> heights;
  for (std::size_t at = svg.find("<rect x="); at != std::string::npos;
       at = svg.find("<rect x=", at + 1)) {
    heights.push_back(attribute(svg.substr(at, svg.find('>', at) - at), "height"));
  }
  REQUIRE(heights.size() == 2);
  CHECK(heights[0] >= 2);
  CHECK(heights[1] > heights[0]);
  // The axis spans the decades from the tail to the bulk, six at most.
  CHECK(contains(svg, ">0.0001<"));
  CHECK(contains(svg, ">100<"));
}
