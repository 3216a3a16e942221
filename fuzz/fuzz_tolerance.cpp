// Tolerance strings (--tol, --histogram-range, --range) as parse_tolerance reads them. An
// accepted zone must be finite and ordered, and its text form must parse back to the same
// zone (reports print it and users paste it back).
#include <cmath>
#include <string_view>

#include "fuzz_support.hpp"
#include "statistics/tolerance.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ncv::fuzz::quiet_and_serial();
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  ncv::fuzz::accepts([&] {
    const ncv::Tolerance zone = ncv::parse_tolerance(text);
    if (!std::isfinite(zone.lower) || !std::isfinite(zone.upper) || zone.lower > zone.upper) {
      __builtin_trap();
    }
    if (!(ncv::parse_tolerance(ncv::to_string(zone)) == zone)) __builtin_trap();
  });
  return 0;
}
