#include <catch2/catch.hpp>

#include <cmath>
#include <utility>
#include <vector>

#include "geometry/linear_patch.hpp"

namespace {

// Whether two doubles are the same bit pattern's value: equal, and zeros of the same sign.
bool same(double x, double y) {
  return x == y && std::signbit(x) == std::signbit(y);
}

}  // namespace

TEST_CASE("a patch's corners are sorted as the swapping network sorts them, zeros' signs too",
          "[linear_patch]") {
  // Every order of values with ties and both zeros: the statistics depend on which zero lands
  // where (sums of signed zeros), so the branch-free sort must pick what the swaps pick.
  const std::vector<double> values = {-1.0, -0.0, 0.0, 0.5, 0.5, 2.0};
  int orders = 0;
  for (const double a : values) {
    for (const double b : values) {
      for (const double c : values) {
        double x = a, y = b, z = c;
        if (x > y) std::swap(x, y);
        if (y > z) std::swap(y, z);
        if (x > y) std::swap(x, y);
        const ncv::LinearPatch p = ncv::make_linear_patch(3.0, a, b, c);
        CHECK(p.area == 3.0);
        CHECK(same(p.lo, x));
        CHECK(same(p.mid, y));
        CHECK(same(p.hi, z));
        CHECK(p.lo <= p.mid);
        CHECK(p.mid <= p.hi);
        ++orders;
      }
    }
  }
  CHECK(orders == 216);
}
