// An extreme error value together with where it occurs.
#pragma once

#include <cstdint>

#include "geometry/vec3.hpp"

namespace ncv {

struct SampleExtreme {
  double value = 0;
  std::uint64_t sample = 0;  // the lowest-index sample attaining it
  Vec3 position{0, 0, 0};
};

}  // namespace ncv
