// The group search with 2 lanes a vector, for SSE2, which every x86-64 has: the default target, no
// pragma. Every header but the two compiled for the target comes before the pragma
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

#include "geometry/closest_point_lanes.hpp"
#include "search/group_search_lanes.hpp"

namespace ncv {

std::size_t search_group_sse2(GroupSearcher::State& state, std::span<const Vec3> queries,
                              std::span<ClosestHit> hits, SearchCounters& counters) {
  return search_group<2>(state, queries, hits, counters);
}

}  // namespace ncv
