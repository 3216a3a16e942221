#include "render/color_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "util/error.hpp"
#include "util/round_nonnegative.hpp"

namespace ncv {

namespace {

// Every shade is fully saturated with a bright dominant channel, so that it keeps its hue
// when a viewer's lighting darkens it: a point just beyond a limit must not read grey. The
// magnitude runs from a light hue at the limit (amber, azure) to the deep one at the end
// of the range (red, indigo), as metrology colour maps do.
constexpr Rgb kWithin{0, 160, 60};
constexpr Rgb kExcessAtLimit{255, 150, 0};
constexpr Rgb kExcessDeep{200, 0, 0};
constexpr Rgb kGougeAtLimit{0, 140, 255};
constexpr Rgb kGougeDeep{40, 0, 170};

// ColorBrewer RdBu, 11 classes, from blue to red.
constexpr Rgb kRdBu[] = {{5, 48, 97},     {33, 102, 172},  {67, 147, 195},  {146, 197, 222},
                         {209, 229, 240}, {247, 247, 247}, {253, 219, 199}, {244, 165, 130},
                         {214, 96, 77},   {178, 24, 43},   {103, 0, 31}};
constexpr int kRdBuMiddle = 5;

// Turbo as the degree-5 polynomial fit by Ruofei Du of Anton Mikhailov's table (Google).
constexpr double kTurbo[3][6] = {
    {0.13572138, 4.61539260, -42.66032258, 132.13108234, -152.94239396, 59.28637943},
    {0.09140261, 2.19418839, 4.84296658, -14.18503333, 4.27729857, 2.82956604},
    {0.10667330, 12.64194608, -60.58204836, 110.36276771, -89.90310912, 27.34824973}};
constexpr int kTurboStops = 65;

// A NaN (no colour map makes one) would come out as 0, as lround's does.
std::uint8_t to_byte(double unit) {
  const double x = std::clamp(unit, 0.0, 1.0) * 255;
  return x >= 0 ? static_cast<std::uint8_t>(round_nonnegative(x)) : 0;
}

// Each byte's b / 255.0, worked out once (the compiler rounds a constant quotient as the
// division at run time does): six divisions a colour were the colour maps' largest cost.
constexpr std::array<double, 256> kByteUnits = [] {
  std::array<double, 256> units{};
  for (std::size_t b = 0; b < units.size(); ++b) units[b] = static_cast<double>(b) / 255.0;
  return units;
}();

Rgb mix(Rgb a, Rgb b, double t) {
  Rgb c{};
  for (int k = 0; k < 3; ++k) {
    c[k] = to_byte(std::lerp(kByteUnits[a[k]], kByteUnits[b[k]], std::clamp(t, 0.0, 1.0)));
  }
  return c;
}

// Where value lies between from and to, 1 when the interval is empty (saturated at once).
double fraction(double value, double from, double to) {
  return from == to ? 1.0 : (value - from) / (to - from);
}

Rgb turbo(double t) {
  t = std::clamp(t, 0.0, 1.0);
  Rgb c{};
  for (int k = 0; k < 3; ++k) {
    double sum = 0;
    for (int p = 5; p >= 0; --p) sum = sum * t + kTurbo[k][p];
    c[k] = to_byte(sum);
  }
  return c;
}

double diverging_centre(ValueRange range) {
  return range.lo <= 0 && range.hi >= 0 ? 0.0 : range.lo + (range.hi - range.lo) / 2;
}

// Position of value on the RdBu scale [0, 10], the centre at 5.
double rdbu_position(double value, ValueRange range) {
  const double centre = diverging_centre(range);
  if (value == centre) return kRdBuMiddle;
  if (value < centre) return kRdBuMiddle * (1 - std::min(1.0, fraction(value, centre, range.lo)));
  return kRdBuMiddle * (1 + std::min(1.0, fraction(value, centre, range.hi)));
}

Rgb diverging(double value, ValueRange range) {
  const double position = std::clamp(rdbu_position(value, range), 0.0, 10.0);
  const int k = std::min(9, static_cast<int>(position));
  return mix(kRdBu[k], kRdBu[k + 1], position - k);
}

Rgb tolerance_color(double value, ValueRange range, const Tolerance& zone) {
  if (value > zone.upper) {
    return mix(kExcessAtLimit, kExcessDeep,
               fraction(value, zone.upper, std::max(range.hi, zone.upper)));
  }
  if (value < zone.lower) {
    return mix(kGougeAtLimit, kGougeDeep,
               fraction(value, zone.lower, std::min(range.lo, zone.lower)));
  }
  return kWithin;
}

std::vector<ColorStop> tolerance_stops(ValueRange range, const Tolerance& zone) {
  std::vector<ColorStop> stops;
  const auto add = [&](double value, Rgb color) {
    if (value >= range.lo && value <= range.hi) stops.push_back({value, color});
  };
  add(range.lo, tolerance_color(range.lo, range, zone));
  add(zone.lower, kGougeAtLimit);
  add(zone.lower, kWithin);
  add(zone.upper, kWithin);
  add(zone.upper, kExcessAtLimit);
  add(range.hi, tolerance_color(range.hi, range, zone));
  return stops;
}

// A half whose end is the centre (a range starting or ending at 0) has no stops.
std::vector<ColorStop> diverging_stops(ValueRange range) {
  std::vector<ColorStop> stops;
  const double centre = diverging_centre(range);
  for (int k = 0; k <= 10; ++k) {
    const double end = k < kRdBuMiddle ? range.lo : range.hi;
    if (k != kRdBuMiddle && end == centre) continue;
    const double t = std::abs(k - kRdBuMiddle) / double(kRdBuMiddle);
    stops.push_back({std::lerp(centre, end, t), kRdBu[k]});
  }
  return stops;
}

std::vector<ColorStop> turbo_stops(ValueRange range) {
  std::vector<ColorStop> stops;
  for (int k = 0; k < kTurboStops; ++k) {
    const double t = k / double(kTurboStops - 1);
    stops.push_back({std::lerp(range.lo, range.hi, t), turbo(t)});
  }
  return stops;
}

}  // namespace

Rgb ColorMap::rgb(double value) const {
  if (std::isnan(value)) return kNoValueColor;
  switch (kind) {
    case ColorMapKind::tolerance:
      return tolerance_color(value, range, tolerance.value());
    case ColorMapKind::diverging:
      return diverging(value, range);
    case ColorMapKind::turbo:
      return turbo(fraction(value, range.lo, range.hi));
  }
  return kNoValueColor;
}

std::vector<ColorStop> ColorMap::stops() const {
  switch (kind) {
    case ColorMapKind::tolerance:
      return tolerance_stops(range, tolerance.value());
    case ColorMapKind::diverging:
      return diverging_stops(range);
    case ColorMapKind::turbo:
      return turbo_stops(range);
  }
  return {};
}

std::string ColorMap::description() const {
  std::string text =
      fmt::format("colour map {} over {}:{}", name_of(kColorMapNames, kind), range.lo, range.hi);
  if (tolerance) text += fmt::format(", tolerance {}", to_string(*tolerance));
  if (kind == ColorMapKind::diverging)
    text += fmt::format(", white at {}", diverging_centre(range));
  return text;
}

ColorMap make_color_map(ColorMapKind kind, ValueRange range,
                        const std::optional<Tolerance>& tolerance) {
  if (!std::isfinite(range.lo) || !std::isfinite(range.hi) || range.lo > range.hi) {
    throw UsageError(
        fmt::format("colour range {}:{} is not a finite interval", range.lo, range.hi));
  }
  if (kind == ColorMapKind::tolerance && !tolerance) {
    throw UsageError("the tolerance colour map needs a tolerance");
  }
  return {kind, range, tolerance};
}

}  // namespace ncv
