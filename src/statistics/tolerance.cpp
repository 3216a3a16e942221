#include "statistics/tolerance.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "util/error.hpp"

namespace ncv {

namespace {

[[noreturn]] void reject(std::string_view text, std::string_view why) {
  throw UsageError(fmt::format("tolerance '{}': {}", text, why));
}

// std::from_chars accepts neither a leading '+' nor surrounding blanks; both are
// refused on purpose so that "0.1 " or "+-1" cannot slip through half-read.
double parse_limit(std::string_view whole, std::string_view part) {
  double value = 0;
  const char* end = part.data() + part.size();
  const auto [ptr, ec] = std::from_chars(part.data(), end, value);
  if (part.empty() || ec == std::errc::invalid_argument) {
    reject(whole, fmt::format("'{}' is not a number", part));
  }
  if (ec == std::errc::result_out_of_range)
    reject(whole, fmt::format("'{}' is out of range", part));
  if (ptr != end)
    reject(whole, fmt::format("unexpected '{}' after the number", std::string_view(ptr, end)));
  if (!std::isfinite(value)) reject(whole, "limits must be finite");
  return value;
}

}  // namespace

Tolerance parse_tolerance(std::string_view text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos) {
    const double half_width = parse_limit(text, text);
    if (half_width < 0) {
      reject(text, "a single value is the half-width of a symmetric zone and must not be negative");
    }
    return {-half_width, half_width};
  }
  const Tolerance zone{parse_limit(text, text.substr(0, colon)),
                       parse_limit(text, text.substr(colon + 1))};
  if (zone.lower > zone.upper) reject(text, "the lower limit exceeds the upper limit");
  return zone;
}

std::string to_string(const Tolerance& tolerance) {
  return fmt::format("{}:{}", tolerance.lower, tolerance.upper);
}

}  // namespace ncv
