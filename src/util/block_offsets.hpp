// Where each item's records start in one array of everybody's records: offsets[i] is start
// plus the sum of count(k) for k < i, offsets[n] the end (which must fit Offset). Two parallel
// passes over fixed blocks (each block's sum, then each block's offsets from its start), so a
// million items cost a few milliseconds instead of a serial loop's ten; integers, so the result is
// exact.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <tbb/parallel_for.h>

#include "util/buffer.hpp"

namespace ncv {

// The items go in blocks of kOffsetBlock, each block's sum made in parallel.
inline constexpr std::size_t kOffsetBlock = std::size_t{1} << 14;

// The first pass: where each block's records start (start, then the running sums of the
// blocks' counts); the last entry is the end of all records.
template <class Offset, class Count>
std::vector<Offset> block_starts(std::size_t n, Count&& count, Offset start = 0) {
  const std::size_t blocks = (n + kOffsetBlock - 1) / kOffsetBlock;
  std::vector<Offset> starts(blocks + 1, 0);
  starts[0] = start;
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    Offset sum = 0;
    for (std::size_t i = b * kOffsetBlock; i < std::min(n, (b + 1) * kOffsetBlock); ++i) {
      sum += static_cast<Offset>(count(i));
    }
    starts[b + 1] = sum;
  });
  for (std::size_t b = 0; b < blocks; ++b) starts[b + 1] += starts[b];
  return starts;
}

// The second pass: visit(i, offset) for every item with its records' offset, the blocks in
// parallel, each from its start in block_starts.
template <class Offset, class Count, class Visit>
void for_each_offset(std::size_t n, Count&& count, const std::vector<Offset>& starts,
                     Visit&& visit) {
  tbb::parallel_for(std::size_t{0}, starts.size() - 1, [&](std::size_t b) {
    Offset at = starts[b];
    for (std::size_t i = b * kOffsetBlock; i < std::min(n, (b + 1) * kOffsetBlock); ++i) {
      visit(i, at);
      at += static_cast<Offset>(count(i));
    }
  });
}

template <class Offset = std::uint64_t, class Count>
Buffer<Offset> block_offsets(std::size_t n, Count&& count, Offset start = 0) {
  const std::vector<Offset> starts = block_starts<Offset>(n, count, start);
  Buffer<Offset> offsets(n + 1);  // every element written below
  offsets[n] = starts.back();
  for_each_offset(n, count, starts, [&](std::size_t i, Offset at) { offsets[i] = at; });
  return offsets;
}

// The items i < n with keep(i), ascending: each one's place among them from block_starts, the
// blocks written in parallel.
template <class Index, class Keep>
Buffer<Index> kept_indices(std::size_t n, Keep&& keep) {
  const auto count = [&](std::size_t i) { return keep(i) ? 1u : 0u; };
  const std::vector<Index> starts = block_starts<Index>(n, count);
  Buffer<Index> kept(starts.back());  // every element written below
  for_each_offset(n, count, starts, [&](std::size_t i, Index at) {
    if (keep(i)) kept[at] = static_cast<Index>(i);
  });
  return kept;
}

}  // namespace ncv
