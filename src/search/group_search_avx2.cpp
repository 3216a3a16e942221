// The group search with 4 lanes a vector, for AVX2.
// Every header but the two compiled for the target comes before the pragma
// (group_search_lanes.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include "search/box_lanes.hpp"
#include "search/group_search_state.hpp"

#if defined(__x86_64__) && defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#elif defined(__x86_64__) && defined(__GNUC__)
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
#if defined(__x86_64__) && defined(__GNUC__)

#include "geometry/closest_point_lanes.hpp"
#include "search/group_search_lanes.hpp"

namespace ncv {

std::size_t search_group_avx2(GroupSearcher::State& state, std::span<const Vec3> queries,
                              std::span<ClosestHit> hits, SearchCounters& counters) {
  return search_group<4>(state, queries, hits, counters);
}

}  // namespace ncv

#endif
#if defined(__x86_64__) && defined(__clang__)
#pragma clang attribute pop
#elif defined(__x86_64__) && defined(__GNUC__)
#pragma GCC pop_options
#endif
