#include "statistics/rank_selection.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <utility>

#include <tbb/parallel_for.h>

#include "util/buffer.hpp"

namespace ncv {

namespace {

constexpr int kDigitBits = 16;
constexpr std::size_t kBuckets = std::size_t{1} << kDigitBits;
constexpr std::size_t kBlock = std::size_t{1} << 18;
constexpr std::uint32_t kNotWanted = ~std::uint32_t{0};
// A bucket up to this size is selected in by nth_element; a larger one by its next digit.
// (Half the finishing part's errors are rounding noise within one top digit: nth_element
// for each of its dozen ranks took 3.3 ms, longer than the pass that counted all values.)
constexpr std::size_t kSelectDirectly = std::size_t{1} << 14;

// Order-preserving: a < b as doubles (not NaN) iff key(a) < key(b), and a == b iff the
// keys are equal (adding +0.0 makes -0.0 the bit pattern of +0.0).
std::uint64_t key(double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v + 0.0);
  return bits >> 63 ? ~bits : bits | (std::uint64_t{1} << 63);
}

double value_of(std::uint64_t k) {
  return std::bit_cast<double>(k >> 63 ? k ^ (std::uint64_t{1} << 63) : ~k);
}

// The 16-bit digit of the key `shift` bits up.
std::size_t digit(double v, int shift) {
  return static_cast<std::size_t>(key(v) >> shift) & (kBuckets - 1);
}

constexpr int kTopShift = 64 - kDigitBits;

// Where each wanted rank lies: its rank within its bucket; the wanted buckets numbered w
// (slot[bucket], kNotWanted for the others), their ranks first_rank[w] .. first_rank[w + 1]
// (both ascend, so each bucket's ranks are consecutive).
struct RankPlaces {
  std::vector<std::uint32_t> slot = std::vector<std::uint32_t>(kBuckets, kNotWanted);
  std::vector<std::size_t> wanted_bucket;
  std::vector<std::size_t> first_rank;
  std::vector<std::size_t> rank_within;

  std::span<const std::size_t> ranks_of(std::size_t w) const {
    return std::span(rank_within).subspan(first_rank[w], first_rank[w + 1] - first_rank[w]);
  }
};

RankPlaces place_ranks(const std::vector<std::size_t>& counts, std::span<const std::size_t> ranks) {
  RankPlaces places;
  places.rank_within.resize(ranks.size());
  std::size_t below = 0, k = 0;
  for (std::size_t r = 0; r < ranks.size(); ++r) {
    while (below + counts[k] <= ranks[r]) below += counts[k++];
    if (places.slot[k] == kNotWanted) {
      places.slot[k] = static_cast<std::uint32_t>(places.wanted_bucket.size());
      places.wanted_bucket.push_back(k);
      places.first_rank.push_back(r);
    }
    places.rank_within[r] = ranks[r] - below;
  }
  places.first_rank.push_back(ranks.size());
  return places;
}

// The values of ranks (ascending) among `values`, whose keys agree above `shift + 16` bits:
// small sets by nth_element, each rank in the part above the one before; larger ones by
// their digit at `shift`, each wanted digit's values selected in again. Below the last digit
// the keys agree in every bit: the values are all one.
void select(Buffer<double>& values, std::span<const std::size_t> ranks, int shift, double* result) {
  if (shift < 0) {
    std::fill_n(result, ranks.size(), values.front());
    return;
  }
  if (values.size() <= kSelectDirectly) {
    std::size_t done = 0;
    for (std::size_t r = 0; r < ranks.size(); ++r) {
      const auto at = values.begin() + static_cast<std::ptrdiff_t>(ranks[r]);
      std::nth_element(values.begin() + static_cast<std::ptrdiff_t>(done), at, values.end());
      result[r] = *at;
      done = ranks[r];
    }
    return;
  }
  std::vector<std::size_t> counts(kBuckets, 0);
  for (const double v : values) ++counts[digit(v, shift)];
  if (counts[digit(values.front(), shift)] == values.size()) {  // one digit: no copy
    select(values, ranks, shift - kDigitBits, result);
    return;
  }
  const RankPlaces places = place_ranks(counts, ranks);
  std::vector<Buffer<double>> wanted(places.wanted_bucket.size());
  for (std::size_t w = 0; w < wanted.size(); ++w) {
    wanted[w].reserve(counts[places.wanted_bucket[w]]);
  }
  for (const double v : values) {
    const std::uint32_t w = places.slot[digit(v, shift)];
    if (w != kNotWanted) wanted[w].push_back(v);
  }
  for (std::size_t w = 0; w < wanted.size(); ++w) {
    select(wanted[w], places.ranks_of(w), shift - kDigitBits, result + places.first_rank[w]);
  }
}

// The top digits' counts, per block of kBlock values (parts[b]) and in all.
struct TopCounts {
  std::vector<std::vector<std::uint32_t>> parts;
  std::vector<std::size_t> all;
};

TopCounts count_top_digits(std::span<const double> values) {
  const std::size_t blocks = (values.size() + kBlock - 1) / kBlock;
  TopCounts counts{std::vector<std::vector<std::uint32_t>>(blocks),
                   std::vector<std::size_t>(kBuckets, 0)};
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    std::vector<std::uint32_t>& part = counts.parts[b];
    part.assign(kBuckets, 0);
    const std::size_t end = std::min(values.size(), (b + 1) * kBlock);
    for (std::size_t i = b * kBlock; i < end; ++i) ++part[digit(values[i], kTopShift)];
  });
  for (const auto& part : counts.parts) {
    for (std::size_t k = 0; k < kBuckets; ++k) counts.all[k] += part[k];
  }
  return counts;
}

// The wanted buckets' values, each plus +0.0, gathered by blocks in parallel, each block
// writing after the earlier blocks' values of the same bucket. In Buffers: not zeroed first,
// and a large one (the finishing part's rounding noise: 7 MB at 1.8 M samples) takes a freed
// buffer kept with its pages backed rather than fresh pages (util/buffer.hpp).
std::vector<Buffer<double>> gather_wanted(std::span<const double> values, const TopCounts& counts,
                                          const RankPlaces& places) {
  const std::size_t wanted = places.wanted_bucket.size();
  std::vector<Buffer<double>> gathered(wanted);
  std::vector<std::vector<std::size_t>> starts(counts.parts.size(),
                                               std::vector<std::size_t>(wanted));
  for (std::size_t w = 0; w < wanted; ++w) {
    std::size_t at = 0;
    for (std::size_t b = 0; b < counts.parts.size(); ++b) {
      starts[b][w] = at;
      at += counts.parts[b][places.wanted_bucket[w]];
    }
    gathered[w].resize(at);  // every element written below
  }
  tbb::parallel_for(std::size_t{0}, counts.parts.size(), [&](std::size_t b) {
    std::vector<std::size_t>& next = starts[b];
    const std::size_t end = std::min(values.size(), (b + 1) * kBlock);
    for (std::size_t i = b * kBlock; i < end; ++i) {
      const std::uint32_t w = places.slot[digit(values[i], kTopShift)];
      if (w != kNotWanted) gathered[w][next[w]++] = values[i] + 0.0;
    }
  });
  return gathered;
}

}  // namespace

std::vector<double> values_at_ranks(std::span<const double> values,
                                    std::span<const std::size_t> ranks) {
  if (ranks.empty()) return {};
  const TopCounts counts = count_top_digits(values);
  const RankPlaces places = place_ranks(counts.all, ranks);
  std::vector<Buffer<double>> gathered = gather_wanted(values, counts, places);
  std::vector<double> result(ranks.size());
  // The wanted buckets selected in side by side.
  tbb::parallel_for(std::size_t{0}, gathered.size(), [&](std::size_t w) {
    select(gathered[w], places.ranks_of(w), kTopShift - kDigitBits,
           result.data() + places.first_rank[w]);
  });
  return result;
}

void sort_values(std::vector<double>& values) {
  constexpr int kBytes = 8;
  const std::size_t n = values.size();
  if (n < 2) return;
  std::vector<std::uint64_t> keys(n), moved(n);
  std::array<std::array<std::size_t, 256>, kBytes> counts{};
  for (std::size_t i = 0; i < n; ++i) {
    keys[i] = key(values[i]);
    for (int b = 0; b < kBytes; ++b) ++counts[b][(keys[i] >> (8 * b)) & 255];
  }
  for (int b = 0; b < kBytes; ++b) {
    std::array<std::size_t, 256>& at = counts[b];
    if (at[(keys[0] >> (8 * b)) & 255] == n) continue;  // every key has this byte
    std::size_t start = 0;
    for (std::size_t& count : at) start += std::exchange(count, start);
    for (const std::uint64_t k : keys) moved[at[(k >> (8 * b)) & 255]++] = k;
    keys.swap(moved);
  }
  for (std::size_t i = 0; i < n; ++i) values[i] = value_of(keys[i]);
}

}  // namespace ncv
