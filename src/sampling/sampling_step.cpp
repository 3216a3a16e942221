#include "sampling/sampling_step.hpp"

#include <charconv>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "util/error.hpp"

namespace ncv {

SamplingStep SamplingStep::parse(const std::string& text) {
  std::string_view number = text;
  SamplingStep step{0, false};
  if (number.ends_with('%')) {
    step.relative = true;
    number.remove_suffix(1);
  }
  const auto [end, error] =
      std::from_chars(number.data(), number.data() + number.size(), step.value);
  if (number.empty() || error != std::errc() || end != number.data() + number.size()) {
    throw UsageError("invalid step '" + text +
                     "': give a length in model units (0.05) or a percentage of the bounding-box "
                     "diagonal (0.1%)");
  }
  if (!std::isfinite(step.value) || step.value <= 0) {
    throw UsageError("invalid step '" + text + "': it must be a positive finite number");
  }
  // Beyond the diagonal no triangle gets a lattice: only its corners would be measured.
  if (step.relative && step.value > 100) {
    throw UsageError("invalid step '" + text +
                     "': at most 100% of the bounding-box diagonal (the default is 0.1%)");
  }
  return step;
}

std::string SamplingStep::text() const {
  return relative ? fmt::format("{}%", value) : fmt::format("{}", value);
}

}  // namespace ncv
