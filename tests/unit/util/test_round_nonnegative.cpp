// round_nonnegative (util/round_nonnegative.hpp): std::lround's value on halves, on the doubles
// next to them, and on random values across the range the sampling and the colour maps use.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "util/round_nonnegative.hpp"

TEST_CASE("round_nonnegative rounds as std::lround", "[util][round]") {
  const auto check = [](double x) {
    INFO(x);
    CHECK(ncv::round_nonnegative(x) == std::lround(x));
  };
  for (double whole = 0; whole < 300; ++whole) {
    for (const double half : {whole, whole + 0.5}) {
      check(half);
      check(std::nextafter(half, 0.0));
      check(std::nextafter(half, 1e300));
    }
  }
  check(0.49999999999999994);  // x + 0.5 rounds up to 1: a shortcut by adding a half fails here
  for (const double big : {2.0e9, 4503599627370495.5, 4503599627370494.5, 0x1p51 + 0.5}) {
    check(big);
  }
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 100000; ++i) {
    check(unit(rng) * 255);
    check(std::ldexp(unit(rng), static_cast<int>(rng() % 40)));
  }
}
