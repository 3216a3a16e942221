// block_offsets and kept_indices (util/block_offsets.hpp): the running sums (from zero or from a
// start) and the kept items a serial loop gives, on sizes around the block boundaries, with
// empty items, on any thread count.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include <tbb/global_control.h>

#include "util/block_offsets.hpp"

TEST_CASE("block offsets are the serial running sums", "[util][offsets]") {
  for (const std::size_t n : {0, 1, 16383, 16384, 16385, 100000}) {
    std::vector<std::uint64_t> counts(n);
    for (std::size_t i = 0; i < n; ++i) counts[i] = (i * 2654435761u >> 7) % 5;  // 0 to 4
    std::vector<std::uint64_t> expected(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) expected[i + 1] = expected[i] + counts[i];
    for (const int threads : {1, 2, 3}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      INFO(n << " items, " << threads << " threads");
      const ncv::Buffer<std::uint64_t> offsets =
          ncv::block_offsets(n, [&](std::size_t i) { return counts[i]; });
      CHECK(std::vector<std::uint64_t>(offsets.begin(), offsets.end()) == expected);
      const ncv::Buffer<std::uint64_t> shifted = ncv::block_offsets(
          n, [&](std::size_t i) { return counts[i]; }, std::uint64_t{7});
      for (std::size_t i = 0; i <= n; ++i) REQUIRE(shifted[i] == expected[i] + 7);
    }
  }
}

TEST_CASE("kept indices are the serial loop's, ascending", "[util][offsets]") {
  for (const std::size_t n : {0, 1, 16383, 16384, 16385, 100000}) {
    const auto keep = [](std::size_t i) { return (i * 2654435761u >> 9) % 3 == 0; };
    std::vector<std::uint32_t> expected;
    for (std::size_t i = 0; i < n; ++i) {
      if (keep(i)) expected.push_back(static_cast<std::uint32_t>(i));
    }
    for (const int threads : {1, 2, 3}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      INFO(n << " items, " << threads << " threads");
      const ncv::Buffer<std::uint32_t> kept = ncv::kept_indices<std::uint32_t>(n, keep);
      CHECK(std::vector<std::uint32_t>(kept.begin(), kept.end()) == expected);
    }
  }
  const ncv::Buffer<std::uint64_t> none =
      ncv::kept_indices<std::uint64_t>(50000, [](std::size_t) { return false; });
  CHECK(none.empty());
}
