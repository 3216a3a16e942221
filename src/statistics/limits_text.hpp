// The text form shared by tolerance zones and value ranges: "LOWER:UPPER", or "T" for the
// symmetric [-T, T]. Each limit is a finite number in the form std::from_chars reads
// (no '+', no blanks, so "0.1 " or "+-1" cannot slip through half-read).
#pragma once

#include <string_view>
#include <utility>

namespace ncv {

// Throws UsageError("WHAT 'TEXT': why") when the text is not of that form, a limit is not
// finite, T is negative or LOWER exceeds UPPER. A zero width passes; callers that need
// width check it themselves.
std::pair<double, double> parse_limits(std::string_view text, std::string_view what);

}  // namespace ncv
