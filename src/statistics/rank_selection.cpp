#include "statistics/rank_selection.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace ncv {

namespace {

constexpr int kDigitBits = 16;
constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
constexpr std::size_t kBlock = std::size_t{1} << 18;
constexpr std::uint32_t kNotWanted = ~std::uint32_t{0};

// Order-preserving: a < b as doubles (not NaN) iff key(a) < key(b), and a == b iff the
// keys are equal (adding +0.0 makes -0.0 the bit pattern of +0.0).
std::uint64_t key(double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v + 0.0);
  return bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);
}

std::size_t bucket(double v) {
  return static_cast<std::size_t>(key(v) >> (64 - kDigitBits));
}

std::vector<std::uint32_t> count_buckets(std::span<const double> values) {
  const std::size_t blocks = (values.size() + kBlock - 1) / kBlock;
  std::vector<std::vector<std::uint32_t>> parts(blocks);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    std::vector<std::uint32_t>& part = parts[b];
    part.assign(kBuckets, 0);
    const std::size_t end = std::min(values.size(), (b + 1) * kBlock);
    for (std::size_t i = b * kBlock; i < end; ++i) ++part[bucket(values[i])];
  });
  std::vector<std::uint32_t> counts(kBuckets, 0);
  for (const auto& part : parts) {
    for (std::size_t k = 0; k < kBuckets; ++k) counts[k] += part[k];
  }
  return counts;
}

}  // namespace

std::vector<double> values_at_ranks(std::span<const double> values,
                                    std::span<const std::size_t> ranks) {
  if (ranks.empty()) return {};
  const std::vector<std::uint32_t> counts = count_buckets(values);
  // Each wanted rank's bucket, and the rank within it; the wanted buckets numbered.
  std::vector<std::uint32_t> slot(kBuckets, kNotWanted);
  std::vector<std::size_t> wanted_bucket, rank_bucket(ranks.size()), rank_within(ranks.size());
  std::size_t below = 0, k = 0;
  for (std::size_t r = 0; r < ranks.size(); ++r) {
    while (below + counts[k] <= ranks[r]) below += counts[k++];
    if (slot[k] == kNotWanted) {
      slot[k] = static_cast<std::uint32_t>(wanted_bucket.size());
      wanted_bucket.push_back(k);
    }
    rank_bucket[r] = slot[k];
    rank_within[r] = ranks[r] - below;
  }
  // The wanted buckets' values, gathered in one pass (in any order: they are selected in).
  std::vector<std::vector<double>> gathered(wanted_bucket.size());
  for (std::size_t w = 0; w < wanted_bucket.size(); ++w) {
    gathered[w].reserve(counts[wanted_bucket[w]]);
  }
  for (const double v : values) {
    const std::uint32_t w = slot[bucket(v)];
    if (w != kNotWanted) gathered[w].push_back(v + 0.0);
  }
  std::vector<double> result(ranks.size());
  tbb::parallel_for(std::size_t{0}, gathered.size(), [&](std::size_t w) {
    std::vector<double>& bucket_values = gathered[w];
    // This bucket's ranks, ascending: each selected in the part above the one before.
    std::size_t done = 0;
    for (std::size_t r = 0; r < ranks.size(); ++r) {
      if (rank_bucket[r] != w) continue;
      const auto at = bucket_values.begin() + static_cast<std::ptrdiff_t>(rank_within[r]);
      std::nth_element(bucket_values.begin() + static_cast<std::ptrdiff_t>(done), at,
                       bucket_values.end());
      result[r] = *at;
      done = rank_within[r];
    }
  });
  return result;
}

}  // namespace ncv
