#include "geometry/linear_patch.hpp"

namespace ncv {

namespace {

// The closed form for lo <= t < hi: hi > lo, and the denominator of the branch taken is
// positive (t < mid implies mid > lo, t >= mid implies hi > mid).
double area_strictly_inside(const LinearPatch& p, double t) {
  if (t < p.mid) {
    const double rise = t - p.lo;
    return p.area * (rise / (p.mid - p.lo)) * (rise / (p.hi - p.lo));
  }
  const double fall = p.hi - t;
  return p.area - p.area * (fall / (p.hi - p.lo)) * (fall / (p.hi - p.mid));
}

}  // namespace

double area_at_most(const LinearPatch& p, double t) {
  if (t < p.lo) return 0;
  if (t >= p.hi) return p.area;
  return area_strictly_inside(p, t);
}

double area_below(const LinearPatch& p, double t) {
  if (t <= p.lo) return 0;
  if (t >= p.hi) return p.area;
  return area_strictly_inside(p, t);
}

}  // namespace ncv
