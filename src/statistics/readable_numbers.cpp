#include "statistics/readable_numbers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace ncv {

namespace {

constexpr double kRelativeResolution = 1e-6;
constexpr int kMostDecimals = 12;

// Decimals that resolve `resolution`: its power of ten, rounded down.
int decimals_for(double resolution) {
  if (!(resolution > 0) || !std::isfinite(resolution)) return 4;
  return std::clamp(static_cast<int>(-std::floor(std::log10(resolution))), 0, kMostDecimals);
}

}  // namespace

std::string fixed_or_zero(double value, int decimals) {
  if (!std::isfinite(value)) return fmt::format("{}", value);
  const double scale = std::pow(10.0, decimals);
  if (std::round(std::abs(value) * scale) == 0) return "0";
  return fmt::format("{:.{}f}", value, decimals);
}

std::string NumberStyle::length(double value) const {
  return fixed_or_zero(value, length_decimals);
}

std::string NumberStyle::length_with_units(double value) const {
  return length(value) + " " + units;
}

std::string NumberStyle::area(double value) const {
  return fixed_or_zero(value, area_decimals);
}

std::string NumberStyle::area_with_units(double value) const {
  return area(value) + " " + units + "\u00b2";
}

std::string NumberStyle::point(Vec3 p) const {
  return fmt::format("({}, {}, {})", length(p[0]), length(p[1]), length(p[2]));
}

NumberStyle number_style(const BoundingBox& part, std::string units) {
  NumberStyle style;
  style.units = std::move(units);
  const double diagonal = part.diagonal();
  if (diagonal > 0 && std::isfinite(diagonal)) {
    const double length_resolution = kRelativeResolution * diagonal;
    style.length_decimals = decimals_for(length_resolution);
    style.area_decimals = decimals_for(length_resolution * diagonal);
  }
  return style;
}

}  // namespace ncv
