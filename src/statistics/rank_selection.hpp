// The values of given ranks in a large array of doubles, without sorting it: an MSD radix
// selection on the values' order-preserving 64-bit keys. One parallel pass counts the top
// 16 bits, a second gathers the few buckets that hold a wanted rank, and each gathered bucket
// is selected in (nth_element). The percentiles' first split points (area_quantiles.cpp) are
// 33 ranks of every sample's error; a multi-way nth_element over the whole array took five
// passes over it, this takes two.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace ncv {

// ranks ascending, each < values.size(); returns the value of each rank in the ascending
// order of the values (not NaN), each plus +0.0: a zero comes out as +0.0, whichever sign
// it had, as -0.0 and +0.0 are equal. The result does not depend on the thread count.
std::vector<double> values_at_ranks(std::span<const double> values,
                                    std::span<const std::size_t> ranks);

}  // namespace ncv
