// std::lround for the non-negative values the sampling and the colour maps round, without the
// libm call: a function call per sample and per colour channel showed as 1 % of `run`'s CPU
// time (docs/PERFORMANCE.md).
#pragma once

#include <cstdint>

namespace ncv {

// x finite, 0 <= x < 2^52: the nearest integer, halves away from zero, as std::lround.
// x - trunc(x) is exact there (x itself below 1, Sterbenz's lemma from 1 on: trunc(x) lies in
// [x / 2, x]), so comparing it with one half decides exactly as lround does.
inline std::int64_t round_nonnegative(double x) {
  const auto whole = static_cast<std::int64_t>(x);
  return whole + (x - static_cast<double>(whole) >= 0.5 ? 1 : 0);
}

}  // namespace ncv
