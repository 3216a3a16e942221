#include "sampling/measuring_order.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include <tbb/parallel_for.h>

#include "geometry/morton_cells.hpp"
#include "util/block_offsets.hpp"
#include "util/bucket_positions.hpp"
#include "util/parallel_over.hpp"

namespace ncv {
namespace {

constexpr std::size_t kSampledPairs = 4096;
// How far past a sampled triangle the next one with own samples is looked for.
constexpr std::size_t kPairReach = 256;
constexpr std::size_t kSortChunks = 4;
// 5 bits an axis: 2^15 cells, each a few times a block of samples; the distance step orders
// each block within itself (search/query_order.hpp). 2^18 cells made the sort's counters
// cost more than the order saved.
constexpr int kBitsPerAxis = 5;

bool has_own_samples(const SampleSet& samples, std::size_t t) {
  return lattice_interior_count(samples.lattice_sizes[t]) > 0;
}

// The first sample that is not a vertex's: where the triangles' own samples begin.
std::uint64_t own_samples_begin(const SampleSet& samples) {
  return samples.first_interior_sample.empty() ? samples.total_samples
                                               : samples.first_interior_sample[0];
}

}  // namespace

bool own_samples_scattered(const SampleSet& samples) {
  const std::size_t triangles = samples.lattice_sizes.size();
  if (!samples.whole() || triangles == 0 ||
      samples.total_samples - own_samples_begin(samples) < kLeastScatteredSamples) {
    return false;
  }
  const Mesh& mesh = samples.mesh;
  const std::size_t stride = std::max<std::size_t>(1, triangles / kSampledPairs);
  std::vector<double> gaps;
  for (std::size_t t = 0; t < triangles; t += stride) {
    if (!has_own_samples(samples, t)) continue;
    const std::size_t last = std::min(triangles, t + 1 + kPairReach);
    for (std::size_t u = t + 1; u < last; ++u) {
      if (!has_own_samples(samples, u)) continue;
      gaps.push_back(norm(mesh.corner(u, 0) - mesh.corner(t, 0)));
      break;
    }
  }
  if (gaps.empty()) return false;
  const auto middle = gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2);
  std::nth_element(gaps.begin(), middle, gaps.end());
  return *middle > bounding_box(mesh).diagonal() / 16;
}

// The triangles with own samples, then a stable counting sort of them by their first corner's
// cell (BucketPositions, chunks side by side), then each one's samples written at its place.
Buffer<std::uint32_t> measuring_order(const SampleSet& samples) {
  if (samples.total_samples > std::numeric_limits<std::uint32_t>::max() ||
      !own_samples_scattered(samples)) {
    return {};
  }
  const Mesh& mesh = samples.mesh;
  const Buffer<std::uint32_t> sampled = kept_indices<std::uint32_t>(
      samples.lattice_sizes.size(), [&](std::size_t t) { return has_own_samples(samples, t); });
  const MortonCells cells(bounding_box(mesh), kBitsPerAxis);
  const auto chunk = [&](std::size_t c, auto&& visit) {
    for (std::size_t k = sampled.size() * c / kSortChunks;
         k < sampled.size() * (c + 1) / kSortChunks; ++k) {
      visit(sampled[k]);
    }
  };
  const auto cell = [&](std::uint32_t t) { return cells.cell(mesh.corner(t, 0)); };
  BucketPositions<std::uint32_t, kSortChunks> positions(
      cells.count(),
      [&](std::size_t c, auto&& emit) { chunk(c, [&](std::uint32_t t) { emit(cell(t)); }); });
  Buffer<std::uint32_t> sorted(sampled.size());  // every element written below
  tbb::parallel_for(std::size_t{0}, kSortChunks, [&](std::size_t c) {
    chunk(c, [&](std::uint32_t t) { sorted[positions.next(c, cell(t))] = t; });
  });

  const auto own_count = [&](std::size_t k) {
    return lattice_interior_count(samples.lattice_sizes[sorted[k]]);
  };
  const Buffer<std::uint64_t> at = block_offsets<std::uint64_t>(sorted.size(), own_count);
  Buffer<std::uint32_t> order(at.back());  // every element written below
  parallel_over(sorted.size(), std::size_t{1} << 10, [&](std::size_t k) {
    const std::uint64_t first = samples.first_interior_sample[sorted[k]];
    const std::uint64_t count = own_count(k);
    for (std::uint64_t s = 0; s < count; ++s) {
      order[at[k] + s] = static_cast<std::uint32_t>(first + s);
    }
  });
  return order;
}

}  // namespace ncv
