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

// Sorts ascending by the same keys, a byte at a time from the lowest (an LSD radix sort; a
// byte all values share is skipped): std::sort's order for values that are not NaN and not
// -0.0, to the bit. Sorting the values inside the percentiles' brackets (40 k each on the
// finishing part) so took their refinement from 18.5 to 14.8 ms on 2 threads.
void sort_values(std::vector<double>& values);

}  // namespace ncv
