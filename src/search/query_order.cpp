#include "search/query_order.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ncv {
namespace {

// Cells per axis: 2^kCellBits; a point's 3 * kCellBits-bit Morton key is sorted in two
// counting passes of kPassBits.
constexpr int kCellBits = 5;
constexpr int kPassBits = 8;
constexpr std::uint32_t kPassBuckets = 1u << kPassBits;
static_assert(3 * kCellBits <= 2 * kPassBits);

// A cell coordinate's bits spread three apart, by table.
constexpr std::array<std::uint32_t, 1 << kCellBits> kSpread = [] {
  std::array<std::uint32_t, 1 << kCellBits> table{};
  for (std::uint32_t v = 0; v < table.size(); ++v) {
    for (int bit = 0; bit < kCellBits; ++bit) table[v] |= ((v >> bit) & 1u) << (3 * bit);
  }
  return table;
}();

// Running sums in place: each bucket's start.
void starts(std::array<std::uint32_t, kPassBuckets>& counts) {
  std::uint32_t sum = 0;
  for (std::uint32_t& c : counts) {
    const std::uint32_t count = c;
    c = sum;
    sum += count;
  }
}

}  // namespace

bool runs_lie_apart(std::span<const Vec3> points, std::size_t run, double reach) {
  std::size_t runs = 0, apart = 0;
  for (std::size_t begin = 0; begin < points.size(); begin += run, ++runs) {
    const std::size_t end = std::min(points.size(), begin + run);
    Vec3 lo = points[begin], hi = lo;
    for (std::size_t k = begin + 1; k < end; ++k) {
      lo = component_min(lo, points[k]);
      hi = component_max(hi, points[k]);
    }
    apart += squared_norm(hi - lo) > reach * reach;
  }
  return 4 * apart > runs;
}

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
  // Each point as its key above its index, so that the passes move one word.
  std::array<std::uint32_t, kMostOrderedPoints> keyed, by_low;
  std::array<std::uint32_t, kPassBuckets> low{}, high{};
  for (std::size_t k = 0; k < n; ++k) {
    std::uint32_t key = 0;
    for (int axis = 0; axis < 3; ++axis) {
      // In [0, cells]: the product rounds to at most `cells`, and truncation is its floor.
      const auto cell =
          static_cast<std::uint32_t>(std::min(cells, (points[k][axis] - lo[axis]) * scale));
      key |= kSpread[cell] << axis;
    }
    keyed[k] = key << 16 | static_cast<std::uint32_t>(k);
    ++low[key & (kPassBuckets - 1)];
    ++high[key >> kPassBits];
  }
  // Two stable counting passes: by the key's low bits, then by its high ones.
  starts(low);
  starts(high);
  for (std::size_t k = 0; k < n; ++k)
    by_low[low[(keyed[k] >> 16) & (kPassBuckets - 1)]++] = keyed[k];
  for (std::size_t k = 0; k < n; ++k) {
    order[high[by_low[k] >> (16 + kPassBits)]++] = static_cast<std::uint16_t>(by_low[k]);
  }
}

}  // namespace ncv
