#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "render/color_map.hpp"
#include "util/error.hpp"

using ncv::ColorMap;
using ncv::ColorMapKind;
using ncv::make_color_map;
using ncv::Rgb;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool reddish(Rgb c) {
  return c[0] > c[1] + 60 && c[0] > c[2] + 60;
}
bool bluish(Rgb c) {
  return c[2] > c[0] + 60 && c[2] > c[1] + 30;
}
bool greenish(Rgb c) {
  return c[1] > c[0] + 60 && c[1] > c[2] + 60;
}
int brightness(Rgb c) {
  return c[0] + c[1] + c[2];
}

// Colour at value as the legend draws it: linear between the stops around it.
Rgb from_stops(const std::vector<ncv::ColorStop>& stops, double value) {
  for (std::size_t k = 1; k < stops.size(); ++k) {
    if (value <= stops[k].value && stops[k - 1].value < stops[k].value) {
      const double t = (value - stops[k - 1].value) / (stops[k].value - stops[k - 1].value);
      Rgb c{};
      for (int i = 0; i < 3; ++i) {
        c[i] = static_cast<std::uint8_t>(
            std::lround(stops[k - 1].color[i] + t * (stops[k].color[i] - stops[k - 1].color[i])));
      }
      return c;
    }
  }
  return stops.back().color;
}

}  // namespace

TEST_CASE("the tolerance map is green inside, red above and blue below", "[color]") {
  const ColorMap map =
      make_color_map(ColorMapKind::tolerance, {-0.3, 0.5}, ncv::Tolerance{-0.05, 0.1});
  CHECK(greenish(map.rgb(0)));
  CHECK(greenish(map.rgb(-0.05)));
  CHECK(greenish(map.rgb(0.1)));
  CHECK(map.rgb(-0.05) == map.rgb(0.1));
  CHECK(reddish(map.rgb(std::nextafter(0.1, 1.0))));
  CHECK(reddish(map.rgb(0.5)));
  CHECK(bluish(map.rgb(std::nextafter(-0.05, -1.0))));
  CHECK(bluish(map.rgb(-0.3)));
  // The shade deepens with the error and saturates at the end of the range.
  CHECK(brightness(map.rgb(0.2)) < brightness(map.rgb(0.11)));
  CHECK(brightness(map.rgb(0.4)) < brightness(map.rgb(0.2)));
  CHECK(map.rgb(0.5) == map.rgb(7));
  CHECK(brightness(map.rgb(-0.2)) < brightness(map.rgb(-0.06)));
  CHECK(map.rgb(-0.3) == map.rgb(-7));
  CHECK(map.rgb(kNaN) == ncv::kNoValueColor);
}

TEST_CASE("the tolerance map needs a tolerance", "[color]") {
  CHECK_THROWS_AS(make_color_map(ColorMapKind::tolerance, {-1, 1}, std::nullopt), ncv::UsageError);
  CHECK_THROWS_AS(make_color_map(ColorMapKind::turbo, {1, -1}, std::nullopt), ncv::UsageError);
  CHECK_THROWS_AS(make_color_map(ColorMapKind::turbo, {0, kNaN}, std::nullopt), ncv::UsageError);
}

TEST_CASE("the diverging map runs blue - white - red with white at zero", "[color]") {
  const ColorMap map = make_color_map(ColorMapKind::diverging, {-0.2, 0.6}, std::nullopt);
  const Rgb white = map.rgb(0);
  CHECK(white[0] == white[1]);
  CHECK(white[1] == white[2]);
  CHECK(white[0] > 240);
  CHECK(bluish(map.rgb(-0.2)));
  CHECK(reddish(map.rgb(0.6)));
  CHECK(bluish(map.rgb(-0.1)));
  CHECK(reddish(map.rgb(0.3)));
  CHECK(map.rgb(-5) == map.rgb(-0.2));
  CHECK(map.rgb(kNaN) == ncv::kNoValueColor);
  SECTION("a range without zero puts white at its middle") {
    const ColorMap positive = make_color_map(ColorMapKind::diverging, {0.2, 0.6}, std::nullopt);
    CHECK(positive.rgb(0.4) == white);
    CHECK(bluish(positive.rgb(0.2)));
  }
  SECTION("a range starting at zero has no blue half") {
    const ColorMap positive = make_color_map(ColorMapKind::diverging, {0, 0.6}, std::nullopt);
    CHECK(positive.rgb(0) == white);
    CHECK(positive.stops().front().value == 0);
    CHECK(positive.stops().front().color == white);
  }
}

TEST_CASE("turbo runs from blue through green to red", "[color]") {
  const ColorMap map = make_color_map(ColorMapKind::turbo, {10, 20}, std::nullopt);
  const Rgb low = map.rgb(11), middle = map.rgb(15), high = map.rgb(19);
  CHECK(bluish(low));
  CHECK(middle[1] > middle[2]);
  CHECK(middle[1] > 200);
  CHECK(reddish(high));
  CHECK(map.rgb(0) == map.rgb(10));
  CHECK(map.rgb(30) == map.rgb(20));
  CHECK(map.rgb(kNaN) == ncv::kNoValueColor);
}

TEST_CASE("the stops reproduce every map", "[color]") {
  const ncv::Tolerance zone{-0.05, 0.1};
  for (const ColorMapKind kind :
       {ColorMapKind::tolerance, ColorMapKind::diverging, ColorMapKind::turbo}) {
    const ColorMap map = make_color_map(kind, {-0.3, 0.5}, zone);
    const std::vector<ncv::ColorStop> stops = map.stops();
    INFO(ncv::name_of(ncv::kColorMapNames, kind));
    REQUIRE(stops.size() >= 2);
    CHECK(stops.front().value == -0.3);
    CHECK(stops.back().value == 0.5);
    for (std::size_t k = 1; k < stops.size(); ++k) CHECK(stops[k - 1].value <= stops[k].value);
    for (int step = 0; step <= 80; ++step) {
      const double value = -0.3 + step * 0.01;
      const Rgb expected = map.rgb(value), drawn = from_stops(stops, value);
      INFO("value " << value);
      // Turbo's stops sample a polynomial, the others are exact up to rounding.
      const int allowed = kind == ColorMapKind::turbo ? 12 : 1;
      for (int i = 0; i < 3; ++i) CHECK(std::abs(expected[i] - drawn[i]) <= allowed);
    }
  }
}

TEST_CASE("colour map names parse and describe", "[color]") {
  CHECK(ncv::parse_name(ncv::kColorMapNames, "turbo") == ColorMapKind::turbo);
  CHECK(ncv::parse_name(ncv::kColorMapNames, "diverging") == ColorMapKind::diverging);
  CHECK(ncv::parse_name(ncv::kColorMapNames, "tolerance") == ColorMapKind::tolerance);
  CHECK_FALSE(ncv::parse_name(ncv::kColorMapNames, "jet").has_value());
  const ColorMap map =
      make_color_map(ColorMapKind::tolerance, {-0.3, 0.5}, ncv::Tolerance{-0.05, 0.1});
  CHECK(map.description() == "colour map tolerance over -0.3:0.5, tolerance -0.05:0.1");
}
