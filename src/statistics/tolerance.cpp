#include "statistics/tolerance.hpp"

#include <fmt/format.h>

#include "statistics/limits_text.hpp"

namespace ncv {

Tolerance parse_tolerance(std::string_view text) {
  const auto [lower, upper] = parse_limits(text, "tolerance");
  return {lower, upper};
}

std::string to_string(const Tolerance& tolerance) {
  return fmt::format("{}:{}", tolerance.lower, tolerance.upper);
}

}  // namespace ncv
