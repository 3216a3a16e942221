// Which way a distance file measures (docs/METHOD.md "Both directions"): forward, the
// workpiece's samples against the nominal; reverse, the nominal's samples against the
// workpiece. Both use one convention: positive where material is left (the workpiece lies
// outside the nominal there), negative for a gouge.
#pragma once

#include <cstdint>

#include "util/enum_names.hpp"

namespace ncv {

enum class Direction : std::uint8_t { forward, reverse };

inline constexpr EnumName<Direction> kDirectionNames[] = {{Direction::forward, "forward"},
                                                          {Direction::reverse, "reverse"}};

}  // namespace ncv
