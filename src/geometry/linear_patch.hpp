// A linear scalar field over one triangle: the unit of every area-weighted measure.
// The error between lattice samples is the linear interpolant of the corner errors
// (paper eq. 8), so integrals, distribution functions and clipped areas of the whole
// field are sums of the closed forms below over the lattice sub-triangles.
#pragma once

#include <algorithm>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace ncv {

struct LinearPatch {
  double area = 0;
  double lo = 0, mid = 0, hi = 0;  // the three corner values, ascending
};

// One compare-and-swap step: the pair `if (x > y) swap(x, y)` leaves, signed zeros
// included, i.e. {std::min(x, y), std::max(y, x)}. SSE2's minsd(y, x) is y < x ? y : x and
// maxsd(x, y) is x > y ? x : y, the same choices; GCC had compiled std::min and std::max here
// to a compare and branch each where the patches are made a range at a time
// (sampling/lattice_triangles.cpp), and those branches mispredicted about once a patch.
struct OrderedPair {
  double lo, hi;
};

inline OrderedPair compare_swap(double x, double y) {
#if defined(__SSE2__)
  const __m128d vx = _mm_set_sd(x), vy = _mm_set_sd(y);
  return {_mm_cvtsd_f64(_mm_min_sd(vy, vx)), _mm_cvtsd_f64(_mm_max_sd(vx, vy))};
#else
  return {std::min(x, y), std::max(y, x)};
#endif
}

// The three compare-and-swap steps (a, b), (b, c), (a, b) of a sorting network, without a
// branch: the corner values of neighbouring patches come in any order.
inline LinearPatch make_linear_patch(double area, double a, double b, double c) {
  const auto [a1, b1] = compare_swap(a, b);
  const auto [b2, c2] = compare_swap(b1, c);
  const auto [lo, mid] = compare_swap(a1, b2);
  return {area, lo, mid, c2};
}

// Integral of the field: area times the mean of the corners (paper eq. 8).
constexpr double integral(const LinearPatch& p) {
  return p.area * ((p.lo + p.mid + p.hi) / 3);
}

// Integral of (field - shift)^2, exact for a linear field.
constexpr double squared_integral(const LinearPatch& p, double shift = 0) {
  const double a = p.lo - shift, b = p.mid - shift, c = p.hi - shift;
  return p.area / 6 * (a * a + b * b + c * c + a * b + b * c + c * a);
}

// The closed form for lo <= t < hi: hi > lo, and the denominator of the branch taken is
// positive (t < mid implies mid > lo, t >= mid implies hi > mid).
inline double area_strictly_inside(const LinearPatch& p, double t) {
  if (t < p.mid) {
    const double rise = t - p.lo;
    return p.area * (rise / (p.mid - p.lo)) * (rise / (p.hi - p.lo));
  }
  const double fall = p.hi - t;
  return p.area - p.area * (fall / (p.hi - p.lo)) * (fall / (p.hi - p.mid));
}

// Area where the field is <= t. The sublevel set is a corner triangle (t below the middle
// value) or the complement of one (t above it), whose area scales with the product of the
// two edge fractions cut off. Inline: the statistics evaluate it millions of times a part.
inline double area_at_most(const LinearPatch& p, double t) {
  if (t < p.lo) return 0;
  if (t >= p.hi) return p.area;
  return area_strictly_inside(p, t);
}

// Area where the field is < t; differs from area_at_most only for a constant patch at t.
inline double area_below(const LinearPatch& p, double t) {
  if (t <= p.lo) return 0;
  if (t >= p.hi) return p.area;
  return area_strictly_inside(p, t);
}

inline double area_above(const LinearPatch& p, double t) {
  return p.area - area_at_most(p, t);
}

}  // namespace ncv
