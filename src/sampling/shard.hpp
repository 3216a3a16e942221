// A share of one sampling job, so that a cluster can measure one part in pieces (`sample
// --shard K/N`): shard K of N holds the samples K·S/N .. (K+1)·S/N of the S samples of the
// whole lattice, each bound rounded down to a multiple of kShardAlignment. Samples are
// numbered mesh vertices first, then each triangle's own lattice points in triangle order
// (sampling.hpp), so a shard is a run of whole triangles but at its two ends. Every sample's
// distance is computed on its own and the distance step's search hint restarts at multiples
// of its block size, which divides the alignment: the shards' results, put back together,
// are the whole job's to the bit, counters included.
#pragma once

#include <cstdint>
#include <string>

namespace ncv {

inline constexpr std::uint64_t kShardAlignment = 512;
inline constexpr std::uint32_t kMaxShards = 100000;

struct Shard {
  std::uint32_t index = 0;  // 0-based; written K/N with K = index + 1
  std::uint32_t count = 1;

  bool operator==(const Shard&) const = default;
  // "K/N" with 1 <= K <= N <= kMaxShards; throws UsageError otherwise.
  static Shard parse(const std::string& text);
  std::string text() const;  // "K/N"
};

struct SampleRange {
  std::uint64_t begin = 0;
  std::uint64_t end = 0;

  std::uint64_t size() const { return end - begin; }
};

SampleRange shard_range(std::uint64_t total_samples, const Shard& shard);

}  // namespace ncv
