// The sampling step as users write it: absolute model units ("0.05") or a percentage of
// the sampled mesh's bounding-box diagonal ("0.1%", the paper's convention).
#pragma once

#include <string>

namespace ncv {

struct SamplingStep {
  double value = 0.1;  // model units, or percent when relative
  bool relative = true;

  // Throws UsageError on anything but a positive finite number with an optional '%'.
  static SamplingStep parse(const std::string& text);
  double resolve(double diagonal) const { return relative ? value / 100.0 * diagonal : value; }
  // The shortest text that parses back to this step: "0.1%", "0.05".
  std::string text() const;
};

}  // namespace ncv
