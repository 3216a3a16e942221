// The size parameter: how many triangles the generated workpieces have, as a fraction of the
// paper's (size 1, "large": about 215 k, 470 k and 1.24 M triangles).
#pragma once

#include <string_view>

namespace ncv::gen {

constexpr double small_size = 0.02;
constexpr double medium_size = 0.2;
constexpr double large_size = 1.0;

// "small", "medium", "large" or a positive factor; throws std::invalid_argument otherwise.
double parse_size(std::string_view text);

// Z-map grid level (2^level cells per 40 mm tile) for a size: 0.078 mm samples up to medium,
// 0.039 mm beyond, where the finest triangles must be far below the 0.15 mm sampling step.
int zmap_level(double size);

}  // namespace ncv::gen
