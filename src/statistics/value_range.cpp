#include "statistics/value_range.hpp"

#include <fmt/format.h>

#include <cmath>

#include "statistics/limits_text.hpp"
#include "util/error.hpp"

namespace ncv {

ValueRange parse_value_range(std::string_view text) {
  const auto [lo, hi] = parse_limits(text, "range");
  if (!(lo < hi)) {
    throw UsageError(fmt::format(
        "range '{}' has no width: its lower limit must be below its upper limit", text));
  }
  if (!std::isfinite(hi - lo)) {
    throw UsageError(fmt::format("range '{}' is wider than a double can hold", text));
  }
  return {lo, hi};
}

}  // namespace ncv
