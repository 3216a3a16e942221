#include "statistics/limits_text.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

#include "util/error.hpp"

namespace ncv {
namespace {

[[noreturn]] void reject(std::string_view what, std::string_view text, std::string_view why) {
  throw UsageError(fmt::format("{} '{}': {}", what, text, why));
}

double parse_limit(std::string_view what, std::string_view whole, std::string_view part) {
  double value = 0;
  const char* end = part.data() + part.size();
  const auto [ptr, ec] = std::from_chars(part.data(), end, value);
  if (part.empty() || ec == std::errc::invalid_argument) {
    reject(what, whole, fmt::format("'{}' is not a number", part));
  }
  if (ec == std::errc::result_out_of_range) {
    reject(what, whole, fmt::format("'{}' is out of range", part));
  }
  if (ptr != end) {
    reject(what, whole,
           fmt::format("unexpected '{}' after the number", std::string_view(ptr, end)));
  }
  if (!std::isfinite(value)) reject(what, whole, "limits must be finite");
  return value;
}

}  // namespace

std::pair<double, double> parse_limits(std::string_view text, std::string_view what) {
  const std::size_t colon = text.find(':');
  if (colon == std::string_view::npos) {
    const double half_width = parse_limit(what, text, text);
    if (half_width < 0) {
      reject(what, text,
             "a single value is the half-width of a symmetric zone and must not be negative");
    }
    return {-half_width, half_width};
  }
  const double lower = parse_limit(what, text, text.substr(0, colon));
  const double upper = parse_limit(what, text, text.substr(colon + 1));
  if (lower > upper) reject(what, text, "the lower limit exceeds the upper limit");
  return {lower, upper};
}

}  // namespace ncv
