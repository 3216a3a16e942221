#include "search/query_order.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ncv {
namespace {

// Cells per axis: 2^kCellBits, a 3 * kCellBits-bit Morton key, sorted in two counting passes.
constexpr int kCellBits = 6;
constexpr int kKeyBits = 3 * kCellBits;
constexpr int kLowBits = 9;

// A cell coordinate's bits spread three apart, by table.
constexpr std::array<std::uint32_t, 1 << kCellBits> kSpread = [] {
  std::array<std::uint32_t, 1 << kCellBits> table{};
  for (std::uint32_t v = 0; v < table.size(); ++v) {
    std::uint32_t spread = 0;
    for (int bit = 0; bit < kCellBits; ++bit) spread |= ((v >> bit) & 1u) << (3 * bit);
    table[v] = spread;
  }
  return table;
}();

// Where each bucket of (key >> shift) & (kBuckets - 1) starts, over all keys. Counted in
// four tallies taken in turn: neighbouring points share buckets, and one tally's increments
// of the same bucket would each wait for the last.
template <std::size_t kBuckets>
std::array<std::uint32_t, kBuckets> bucket_starts(std::span<const std::uint32_t> keys, int shift) {
  std::array<std::array<std::uint32_t, kBuckets>, 4> tally{};
  for (std::size_t k = 0; k < keys.size(); ++k) ++tally[k % 4][(keys[k] >> shift) & (kBuckets - 1)];
  std::array<std::uint32_t, kBuckets> start;
  std::uint32_t sum = 0;
  for (std::size_t b = 0; b < kBuckets; ++b) {
    start[b] = sum;
    sum += tally[0][b] + tally[1][b] + tally[2][b] + tally[3][b];
  }
  return start;
}

}  // namespace

void spatial_order(std::span<const Vec3> points, std::span<std::uint16_t> order) {
  const std::size_t n = points.size();
  double lo[3], hi[3];
  for (int axis = 0; axis < 3; ++axis) lo[axis] = hi[axis] = n > 0 ? points[0][axis] : 0.0;
  for (const Vec3& p : points) {
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = std::min(lo[axis], p[axis]);
      hi[axis] = std::max(hi[axis], p[axis]);
    }
  }
  // Cubic cells, sized by the box's longest side.
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double cells = static_cast<double>((1 << kCellBits) - 1);
  const double scale = extent > 0 ? cells / extent : 0.0;
  std::array<std::uint32_t, kMostOrderedPoints> keys_store;
  std::array<std::uint16_t, kMostOrderedPoints> by_low;
  const std::span<std::uint32_t> keys(keys_store.data(), n);
  for (std::size_t k = 0; k < n; ++k) {
    std::uint32_t key = 0;
    for (int axis = 0; axis < 3; ++axis) {
      // In [0, cells]: the product rounds to at most `cells`, and truncation is its floor.
      const auto cell =
          static_cast<std::uint32_t>(std::min(cells, (points[k][axis] - lo[axis]) * scale));
      key |= std::uint32_t{kSpread[cell]} << axis;
    }
    keys[k] = key;
  }
  // Two stable counting passes: by the low bits, then by the high ones.
  auto low = bucket_starts<(1u << kLowBits)>(keys, 0);
  for (std::size_t k = 0; k < n; ++k) {
    by_low[low[keys[k] & ((1u << kLowBits) - 1)]++] = static_cast<std::uint16_t>(k);
  }
  auto high = bucket_starts<(1u << (kKeyBits - kLowBits))>(keys, kLowBits);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint16_t i = by_low[k];
    order[high[keys[i] >> kLowBits]++] = i;
  }
}

}  // namespace ncv
