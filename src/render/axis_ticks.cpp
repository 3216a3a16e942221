#include "render/axis_ticks.hpp"

#include <cmath>

namespace ncv {

namespace {

// 10^|k| by repeated multiplication, exact for |k| <= 22 (and as close as std::pow beyond).
double power_of_ten(int k) {
  double p = 1;
  for (int i = 0; i < std::abs(k); ++i) p *= 10;
  return p;
}

// Dividing by an exact power of ten rounds once, to the double nearest the decimal.
double scaled(double integer, int exponent) {
  return exponent >= 0 ? integer * power_of_ten(exponent) : integer / power_of_ten(exponent);
}

}  // namespace

std::vector<double> axis_ticks(double lo, double hi, int wanted) {
  if (!(hi > lo) || wanted < 1) return {lo};
  const double raw = (hi - lo) / wanted;
  int exponent = static_cast<int>(std::floor(std::log10(raw)));
  const double mantissa = raw / std::pow(10.0, exponent);
  double nice = mantissa <= 1 ? 1 : mantissa <= 2 ? 2 : mantissa <= 5 ? 5 : 10;
  if (nice == 10) {
    nice = 1;
    ++exponent;
  }
  std::vector<double> ticks;
  // Adding +0.0 keeps a zero tick from printing as "-0".
  for (double m = std::floor(lo / scaled(nice, exponent));; ++m) {
    const double value = scaled(m * nice, exponent) + 0.0;
    if (value > hi) break;
    if (value >= lo) ticks.push_back(value);
  }
  return ticks;
}

}  // namespace ncv
