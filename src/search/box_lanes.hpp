// The search's box prefilter, four boxes at a time in float: which lanes of a BoxBlock may
// hold a triangle within `bound` of the query, where bound = best + margin is the search's
// double-precision bound (closest_point_search.hpp).
//
// Why float is safe. Let s be the coordinate scale (the largest magnitude of the query and of
// the grid box, which contains every box corner). The query is rounded to float (error at
// most 2^-24 s per axis); each per-axis gap is one float subtraction of numbers below
// 2.0001 s, then a max with 0 (monotone), so each computed gap is within 3.0001 * 2^-24 s of
// the exact gap of the query to the (float) box, and the gap vector within sqrt(3) times
// that, under 2^-21 s, in length. The sum of squares adds at most four roundings, a factor
// below 1 + 2^-21. A lane is rejected when that sum exceeds
//     limit = float((bound + 2^-20 s)^2 * (1 + 2^-19)) >= (bound + 2^-20 s)^2 * (1 + 2^-20)
// (rounding to the nearest float loses at most 2^-24 of it),
// so the computed gap length exceeds bound + 2^-20 s and the exact one exceeds bound. The
// box contains the triangle, so the triangle is farther than bound too: rejecting it is
// what the search's stopping argument already allows. Rounding only ever makes the filter
// let more lanes through. The filter is used only while 2^-40 <= s <= 2^60 (no overflow to
// infinity, no underflow of the limit); otherwise every lane passes.
//
// SSE2 (every x86-64) does the four lanes at once; other targets run the scalar loop,
// which computes the same float operations in the same order (the unit tests compare the
// two).
#pragma once

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "search/reference_boxes.hpp"

namespace ncv {

inline constexpr double kBoxFilterSlack = 0x1p-20;

// Whether the float filter may be used at coordinate scale s.
constexpr bool box_filter_usable(double scale) {
  return scale >= 0x1p-40 && scale <= 0x1p60;
}

// The float limit for a search bound at coordinate scale s (see above); +inf for an
// infinite bound. A finite bound is at most 4 s (the query and every triangle lie within
// s of the origin), so with s <= 2^60 the limit stays below 2^124, inside float's range.
inline float box_filter_limit(double bound, double scale) {
  const double grown = bound + kBoxFilterSlack * scale;
  return static_cast<float>(grown * grown * (1 + 2 * kBoxFilterSlack));
}

// Bit k set when lane k of the block may be within the bound; squared[k] receives the
// lane's squared float gap, for re-checking once the bound has shrunk.
inline unsigned near_lanes_scalar(const BoxBlock& block, const float q[3], float limit,
                                  float squared[kBoxLanes]) {
  unsigned near = 0;
  for (int lane = 0; lane < kBoxLanes; ++lane) {
    float sum = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const float below = block.lo[axis][lane] - q[axis];
      const float above = q[axis] - block.hi[axis][lane];
      const float gap = std::max(std::max(below, above), 0.0f);
      sum = axis == 0 ? gap * gap : sum + gap * gap;
    }
    squared[lane] = sum;
    if (sum <= limit) near |= 1u << lane;
  }
  return near;
}

// The query point and the limit in every lane, made once for the blocks of a cell rather
// than once per block.
struct LaneQuery {
#if defined(__SSE2__)
  __m128 point[3];
  __m128 limit;
#else
  float point[3];
  float limit;
#endif
};

inline LaneQuery lane_query(const float q[3], float limit) {
#if defined(__SSE2__)
  return {{_mm_set1_ps(q[0]), _mm_set1_ps(q[1]), _mm_set1_ps(q[2])}, _mm_set1_ps(limit)};
#else
  return {{q[0], q[1], q[2]}, limit};
#endif
}

inline unsigned near_lanes(const BoxBlock& block, const LaneQuery& query,
                           float squared[kBoxLanes]) {
#if defined(__SSE2__)
  const __m128 zero = _mm_setzero_ps();
  __m128 sum = zero;
  for (int axis = 0; axis < 3; ++axis) {
    const __m128 below = _mm_sub_ps(_mm_load_ps(block.lo[axis]), query.point[axis]);
    const __m128 above = _mm_sub_ps(query.point[axis], _mm_load_ps(block.hi[axis]));
    // _mm_max_ps(a, b) is a > b ? a : b, as std::max(b, a) is: the same value for non-NaN
    // input, and no NaN arises (finite or infinite boxes, finite query, see above).
    const __m128 gap = _mm_max_ps(_mm_max_ps(below, above), zero);
    sum = axis == 0 ? _mm_mul_ps(gap, gap) : _mm_add_ps(sum, _mm_mul_ps(gap, gap));
  }
  _mm_storeu_ps(squared, sum);
  return static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(sum, query.limit)));
#else
  return near_lanes_scalar(block, query.point, query.limit, squared);
#endif
}

// The same test with a box [lo, hi] of queries in place of the point (the group search,
// group_search.hpp): the box is rounded outward to floats, so each float gap is at most the
// exact gap to it plus one subtraction's rounding, inside the analysis above.
struct LaneBox {
#if defined(__SSE2__)
  __m128 lo[3];
  __m128 hi[3];
  __m128 limit;
#else
  float lo[3];
  float hi[3];
  float limit;
#endif
};

inline LaneBox lane_box(const float lo[3], const float hi[3], float limit) {
#if defined(__SSE2__)
  return {{_mm_set1_ps(lo[0]), _mm_set1_ps(lo[1]), _mm_set1_ps(lo[2])},
          {_mm_set1_ps(hi[0]), _mm_set1_ps(hi[1]), _mm_set1_ps(hi[2])},
          _mm_set1_ps(limit)};
#else
  return {{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}, limit};
#endif
}

inline unsigned near_lanes_scalar(const BoxBlock& block, const float lo[3], const float hi[3],
                                  float limit, float squared[kBoxLanes]) {
  unsigned near = 0;
  for (int lane = 0; lane < kBoxLanes; ++lane) {
    float sum = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const float below = block.lo[axis][lane] - hi[axis];
      const float above = lo[axis] - block.hi[axis][lane];
      const float gap = std::max(std::max(below, above), 0.0f);
      sum = axis == 0 ? gap * gap : sum + gap * gap;
    }
    squared[lane] = sum;
    if (sum <= limit) near |= 1u << lane;
  }
  return near;
}

inline unsigned near_lanes(const BoxBlock& block, const LaneBox& box, float squared[kBoxLanes]) {
#if defined(__SSE2__)
  const __m128 zero = _mm_setzero_ps();
  __m128 sum = zero;
  for (int axis = 0; axis < 3; ++axis) {
    const __m128 below = _mm_sub_ps(_mm_load_ps(block.lo[axis]), box.hi[axis]);
    const __m128 above = _mm_sub_ps(box.lo[axis], _mm_load_ps(block.hi[axis]));
    const __m128 gap = _mm_max_ps(_mm_max_ps(below, above), zero);
    sum = axis == 0 ? _mm_mul_ps(gap, gap) : _mm_add_ps(sum, _mm_mul_ps(gap, gap));
  }
  _mm_storeu_ps(squared, sum);
  return static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(sum, box.limit)));
#else
  return near_lanes_scalar(block, box.lo, box.hi, box.limit, squared);
#endif
}

}  // namespace ncv
