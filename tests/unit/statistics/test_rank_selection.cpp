// values_at_ranks (statistics/rank_selection.hpp) against a full sort, on values with ties,
// both zeros, dense clusters in one radix bucket and a wide spread, on any thread count.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include <tbb/global_control.h>

#include "statistics/rank_selection.hpp"

namespace {

std::vector<double> mixed_values(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<double> values(count);
  for (double& v : values) {
    const std::uint64_t kind = random() % 6;
    const double u = static_cast<double>(random() >> 11) * 0x1p-53;
    // Distinct values sharing the keys' top 32 bits (kind 3): the selection goes down to
    // lower digits, as it must for a part whose errors are mostly rounding noise.
    v = kind == 0   ? u * 0x1p-50
        : kind == 1 ? (random() % 2 ? 0.0 : -0.0)
        : kind == 2 ? static_cast<double>(random() % 3) - 1
        : kind == 3 ? 1 + u * 0x1p-30
                    : (u - 0.5) * 1e6;
  }
  return values;
}

}  // namespace

TEST_CASE("values at ranks are those of the sorted values", "[stats][quantiles]") {
  for (const std::size_t count : {1, 7, 1000, 700000}) {
    const std::vector<double> values = mixed_values(count, count);
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::size_t> ranks{0};
    for (std::size_t k = 1; k <= 32; ++k) {
      const std::size_t rank = (count * k) / 32;
      if (rank > ranks.back() && rank < count) ranks.push_back(rank);
    }
    if (count > 1) ranks.push_back(count - 1);
    const auto run = [&](int threads) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      return ncv::values_at_ranks(values, ranks);
    };
    const std::vector<double> one = run(1), two = run(2);
    for (std::size_t r = 0; r < ranks.size(); ++r) {
      INFO(count << " values, rank " << ranks[r]);
      CHECK(std::bit_cast<std::uint64_t>(one[r]) ==
            std::bit_cast<std::uint64_t>(sorted[ranks[r]] + 0.0));
      CHECK(std::bit_cast<std::uint64_t>(two[r]) == std::bit_cast<std::uint64_t>(one[r]));
    }
  }
}

TEST_CASE("sorted by their keys, values are in std::sort's order to the bit", "[stats]") {
  for (const std::size_t count : {0, 1, 2, 300, 40000}) {
    std::vector<double> values = mixed_values(count, count + 7);
    for (double& v : values) v += 0.0;  // no -0.0, as the function asks
    std::vector<double> expected = values;
    std::sort(expected.begin(), expected.end());
    ncv::sort_values(values);
    REQUIRE(values.size() == expected.size());
    for (std::size_t k = 0; k < values.size(); ++k) {
      INFO(count << " values, position " << k);
      CHECK(std::bit_cast<std::uint64_t>(values[k]) == std::bit_cast<std::uint64_t>(expected[k]));
    }
  }
}
