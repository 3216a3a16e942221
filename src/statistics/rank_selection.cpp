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

// The wanted buckets' values (slot[bucket] numbers them), gathered by blocks in parallel and
// joined in block order; their order is of no matter, as they are selected in.
std::vector<std::vector<double>> gather_wanted(std::span<const double> values,
                                               const std::vector<std::uint32_t>& slot,
                                               std::size_t wanted) {
  const std::size_t blocks = (values.size() + kBlock - 1) / kBlock;
  std::vector<std::vector<std::vector<double>>> parts(blocks);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    std::vector<std::vector<double>>& part = parts[b];
    part.resize(wanted);
    const std::size_t end = std::min(values.size(), (b + 1) * kBlock);
    for (std::size_t i = b * kBlock; i < end; ++i) {
      const std::uint32_t w = slot[bucket(values[i])];
      if (w != kNotWanted) part[w].push_back(values[i] + 0.0);
    }
  });
  std::vector<std::vector<double>> gathered(wanted);
  tbb::parallel_for(std::size_t{0}, wanted, [&](std::size_t w) {
    std::size_t size = 0;
    for (const auto& part : parts) size += part[w].size();
    gathered[w].reserve(size);
    for (const auto& part : parts)
      gathered[w].insert(gathered[w].end(), part[w].begin(), part[w].end());
  });
  return gathered;
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
  std::vector<std::vector<double>> gathered = gather_wanted(values, slot, wanted_bucket.size());
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
