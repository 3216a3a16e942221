// The tolerance zone [lower, upper] of the signed error: a point is within tolerance when
// lower <= d <= upper, in excess (material left) above upper, gouged below lower.
#pragma once

#include <string>
#include <string_view>

namespace ncv {

struct Tolerance {
  double lower = 0;
  double upper = 0;

  bool operator==(const Tolerance&) const = default;
};

enum class ToleranceClass { gouge, within, excess };

// "-0.05:0.1" gives [-0.05, 0.1]; "0.1" gives the symmetric zone [-0.1, 0.1].
// Throws UsageError naming the text when it does not describe a finite zone.
Tolerance parse_tolerance(std::string_view text);

// The inverse of parse_tolerance: "lower:upper", each the shortest round-tripping form.
std::string to_string(const Tolerance& tolerance);

constexpr ToleranceClass classify(double d, const Tolerance& tolerance) {
  if (d < tolerance.lower) return ToleranceClass::gouge;
  if (d > tolerance.upper) return ToleranceClass::excess;
  return ToleranceClass::within;
}

}  // namespace ncv
