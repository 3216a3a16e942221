#include "mesh/facet_weld.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <vector>

#include <tbb/parallel_for.h>

#include "util/block_offsets.hpp"
#include "util/buffer.hpp"

namespace ncv {
namespace {

constexpr std::size_t kFacetBytes = 50;
constexpr std::size_t kCornerOffset = 12;  // after the facet's normal
constexpr unsigned kPartitionBits = 6;
constexpr std::size_t kPartitions = std::size_t{1} << kPartitionBits;
constexpr std::uint64_t kCornerBlock = 1 << 16;

// A corner's coordinates as float bits, -0 as +0: equal bits, equal points. (The double a
// float converts to exactly, plus 0.0, is what VertexWelder compares: the same equality.)
using CornerBits = std::array<std::uint32_t, 3>;

// A corner as its partition holds it. Its hash is computed again where needed (counting,
// placing, probing) rather than stored: a few multiplications against 8 more bytes a corner
// in the weld's largest array.
struct Record {
  std::uint32_t corner;
  CornerBits bits;
};

std::array<float, 3> corner_floats(const char* facets, std::uint64_t corner) {
  std::array<float, 3> xyz;
  std::memcpy(xyz.data(), facets + corner / 3 * kFacetBytes + kCornerOffset + corner % 3 * 12,
              sizeof xyz);
  return xyz;
}

CornerBits corner_bits(const std::array<float, 3>& xyz) {
  CornerBits bits;
  for (int k = 0; k < 3; ++k) bits[k] = std::bit_cast<std::uint32_t>(xyz[k] + 0.0f);
  return bits;
}

bool is_finite(const std::array<float, 3>& xyz) {
  return std::isfinite(xyz[0]) && std::isfinite(xyz[1]) && std::isfinite(xyz[2]);
}

std::uint64_t hash_bits(const CornerBits& bits) {
  std::uint64_t h = (std::uint64_t{bits[0]} << 32 | bits[1]) * 0x9E3779B97F4A7C15ull;
  h ^= (h >> 29) ^ (std::uint64_t{bits[2]} * 0xC2B2AE3D27D4EB4Full);
  h *= 0x165667B19E3779F9ull;
  return h ^ (h >> 32);
}

std::size_t partition_of(std::uint64_t hash) {
  return static_cast<std::size_t>(hash >> (64 - kPartitionBits));
}

// The corners as records grouped by partition, in corner order within each: per block of
// corners a count per partition, then each block writes its records where its counts say.
struct Partitioned {
  Buffer<Record> records;
  std::array<std::uint64_t, kPartitions + 1> begin{};
  std::optional<std::uint64_t> non_finite;
};

Partitioned partition_corners(const char* facets, std::uint64_t corners) {
  const std::size_t blocks = (corners + kCornerBlock - 1) / kCornerBlock;
  std::vector<std::array<std::uint64_t, kPartitions>> counts(blocks);
  std::vector<std::uint64_t> bad(blocks, corners);  // each block's first non-finite corner
  const auto block_end = [&](std::size_t b) { return std::min(corners, (b + 1) * kCornerBlock); };
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    counts[b].fill(0);
    for (std::uint64_t c = b * kCornerBlock; c < block_end(b); ++c) {
      const std::array<float, 3> xyz = corner_floats(facets, c);
      ++counts[b][partition_of(hash_bits(corner_bits(xyz)))];
      if (!is_finite(xyz) && bad[b] == corners) bad[b] = c;
    }
  });
  Partitioned out;
  const auto first_bad = std::min_element(bad.begin(), bad.end());
  if (first_bad != bad.end() && *first_bad < corners) {
    out.non_finite = *first_bad / 3;
    return out;
  }
  // Block b's first record of partition p: the partitions before p, then p's earlier blocks.
  std::vector<std::array<std::uint64_t, kPartitions>> at(blocks);
  std::uint64_t next = 0;
  for (std::size_t p = 0; p < kPartitions; ++p) {
    out.begin[p] = next;
    for (std::size_t b = 0; b < blocks; ++b) {
      at[b][p] = next;
      next += counts[b][p];
    }
  }
  out.begin[kPartitions] = next;
  out.records.resize(corners);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    for (std::uint64_t c = b * kCornerBlock; c < block_end(b); ++c) {
      const CornerBits bits = corner_bits(corner_floats(facets, c));
      out.records[at[b][partition_of(hash_bits(bits))]++] = {static_cast<std::uint32_t>(c), bits};
    }
  });
  return out;
}

// Each corner's first occurrence: the corner, in file order, with the same coordinates.
// Partitions are welded side by side, each with its own table of record indices.
Buffer<std::uint32_t> first_occurrences(const Partitioned& parts, std::uint64_t corners) {
  Buffer<std::uint32_t> first(corners);
  tbb::parallel_for(std::size_t{0}, kPartitions, [&](std::size_t p) {
    const std::uint64_t begin = parts.begin[p], end = parts.begin[p + 1];
    const std::size_t mask = std::bit_ceil(std::max<std::uint64_t>(16, 2 * (end - begin))) - 1;
    // Record index from `begin`, plus 1; 0 = empty.
    std::vector<std::uint32_t> table(mask + 1, 0);
    for (std::uint64_t r = begin; r < end; ++r) {
      const Record& record = parts.records[r];
      std::size_t slot = static_cast<std::size_t>(hash_bits(record.bits)) & mask;
      for (;; slot = (slot + 1) & mask) {
        if (table[slot] == 0) {
          table[slot] = static_cast<std::uint32_t>(r - begin + 1);
          first[record.corner] = record.corner;
          break;
        }
        const Record& earlier = parts.records[begin + table[slot] - 1];
        if (earlier.bits == record.bits) {
          first[record.corner] = earlier.corner;
          break;
        }
      }
    }
  });
  return first;
}

}  // namespace

WeldedFacets weld_binary_facets(const char* facets, std::uint64_t count) {
  const std::uint64_t corners = 3 * count;
  WeldedFacets out;
  Buffer<std::uint32_t> first;
  {
    const Partitioned parts = partition_corners(facets, corners);
    if (parts.non_finite) {
      out.non_finite = parts.non_finite;
      return out;
    }
    first = first_occurrences(parts, corners);
  }
  // Vertices are the first occurrences, numbered in file order.
  // 32-bit: the corners' count fits (parse_binary_stl refuses more), so their vertices' does.
  const Buffer<std::uint32_t> vertex =
      block_offsets<std::uint32_t>(corners, [&](std::size_t c) { return first[c] == c ? 1 : 0; });
  Mesh& mesh = out.mesh;
  mesh.vertices.resize(vertex.back());
  mesh.triangles.resize(count);
  tbb::parallel_for(std::uint64_t{0}, count, [&](std::uint64_t t) {
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t c = 3 * t + k;
      mesh.triangles[t][k] = vertex[first[c]];
      if (first[c] == c) {
        const std::array<float, 3> xyz = corner_floats(facets, c);
        mesh.vertices[vertex[c]] = Vec3(xyz[0], xyz[1], xyz[2]);
      }
    }
  });
  return out;
}

}  // namespace ncv
