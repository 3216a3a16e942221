// The sampling step as users write it: absolute model units ("0.05") or a percentage of
// the workpiece bounding-box diagonal ("0.1%", the paper's convention).
#pragma once

#include <string>

namespace ncv {

struct SamplingStep {
  double value = 0;  // model units, or percent when relative
  bool relative = false;

  // Throws UsageError on anything but a positive finite number with an optional '%'.
  static SamplingStep parse(const std::string& text);
  double resolve(double diagonal) const { return relative ? value / 100.0 * diagonal : value; }
};

}  // namespace ncv
