// Sampling step strings (--step) as SamplingStep::parse reads them. An accepted step must
// be a positive finite length or percentage, so no step can reach the lattice as zero,
// negative or NaN.
#include <cmath>
#include <string>

#include "fuzz_support.hpp"
#include "sampling/sampling_step.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ncv::fuzz::quiet_and_serial();
  const std::string text(reinterpret_cast<const char*>(data), size);
  ncv::fuzz::accepts([&] {
    const ncv::SamplingStep step = ncv::SamplingStep::parse(text);
    if (!(step.value > 0) || !std::isfinite(step.value)) __builtin_trap();
  });
  return 0;
}
