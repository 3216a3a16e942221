// A point as the JSON array [x, y, z]: how every file and report of the suite writes one.
#pragma once

#include <nlohmann/json.hpp>

#include "geometry/vec3.hpp"

namespace ncv {

inline nlohmann::json point_json(const Vec3& p) {
  return {p[0], p[1], p[2]};
}

}  // namespace ncv
