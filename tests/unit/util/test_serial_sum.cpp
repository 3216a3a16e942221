// serial_sum (util/serial_sum.hpp): the bits of a loop adding the terms in index order, on
// terms whose sum depends on the order of the additions, on any thread count.
#include <catch2/catch.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <tbb/global_control.h>

#include "util/serial_sum.hpp"

TEST_CASE("a serial sum is the serial loop's to the bit", "[util][sum]") {
  // Magnitudes from 1e-8 to 1e8 of both signs: a sum in another order (blocks, pairs)
  // rounds differently.
  const auto term = [](std::size_t i) {
    const double magnitude = std::pow(10.0, static_cast<double>(i * 2654435761u % 17) - 8.0);
    return (i % 3 == 0 ? -1.0 : 1.0) * magnitude * (1.0 + 1e-3 * static_cast<double>(i % 101));
  };
  for (const std::size_t n : {0, 1, 16383, 16385, 200000}) {
    double expected = 0;
    for (std::size_t i = 0; i < n; ++i) expected += term(i);
    double pairs = 0;  // the same terms in another order, for the test's own sake
    for (std::size_t i = 0; i + 1 < n; i += 2) pairs += term(i) + term(i + 1);
    if (n == 200000) REQUIRE(pairs != expected);
    for (const int threads : {1, 2, 3}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      INFO(n << " terms, " << threads << " threads");
      CHECK(std::bit_cast<std::uint64_t>(ncv::serial_sum(n, term)) ==
            std::bit_cast<std::uint64_t>(expected));
    }
  }
}
