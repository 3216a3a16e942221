// Shards of a sampling job: "K/N" parsed and refused, and the ranges of the N shards cover
// the samples once, in order, at multiples of the alignment (so each shard's search hint
// restarts where the whole job's does).
#include <catch2/catch.hpp>

#include <vector>

#include "sampling/shard.hpp"
#include "util/error.hpp"

using ncv::Shard;

TEST_CASE("a shard is written K/N, counted from 1", "[shard]") {
  CHECK(Shard::parse("1/4") == Shard{0, 4});
  CHECK(Shard::parse("4/4") == Shard{3, 4});
  CHECK(Shard::parse("1/1") == Shard{0, 1});
  CHECK(Shard::parse("7/100000").text() == "7/100000");
  for (const char* bad :
       {"0/4", "5/4", "1/0", "1/100001", "x/3", "1/3/3", "1", "/", "-1/3", "1/ 3", ""}) {
    INFO(bad);
    CHECK_THROWS_AS(Shard::parse(bad), ncv::UsageError);
  }
}

TEST_CASE("the shards of a job cover its samples once, aligned", "[shard]") {
  for (const std::uint64_t total :
       {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{511}, std::uint64_t{1000},
        std::uint64_t{1198984}, std::uint64_t{50'000'000'007}}) {
    for (const std::uint32_t n : {1u, 2u, 3u, 7u, 64u, 1000u}) {
      INFO("total " << total << ", " << n << " shards");
      std::uint64_t next = 0;
      for (std::uint32_t k = 0; k < n; ++k) {
        const ncv::SampleRange range = ncv::shard_range(total, Shard{k, n});
        REQUIRE(range.begin == next);
        REQUIRE(range.end >= range.begin);
        if (k + 1 < n) REQUIRE(range.end % ncv::kShardAlignment == 0);
        next = range.end;
      }
      REQUIRE(next == total);
    }
  }
}

TEST_CASE("shards share the samples evenly but for the alignment", "[shard]") {
  const std::uint64_t total = 10'000'000;
  for (std::uint32_t k = 0; k < 4; ++k) {
    const ncv::SampleRange range = ncv::shard_range(total, Shard{k, 4});
    CHECK(range.size() + ncv::kShardAlignment > total / 4);
    CHECK(range.size() < total / 4 + ncv::kShardAlignment);
  }
}
