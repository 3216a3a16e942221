// An interval of error values that a picture spans: the histogram's axis, the colour map's
// range. Unlike a tolerance zone it says nothing about pass or fail.
#pragma once

#include <string_view>

namespace ncv {

struct ValueRange {
  double lo = 0;
  double hi = 0;
};

// "LO:HI", or "R" for [-R, R] (statistics/limits_text.hpp); the range must have width.
// Throws UsageError("range '...': ...") otherwise.
ValueRange parse_value_range(std::string_view text);

}  // namespace ncv
