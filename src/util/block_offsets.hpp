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

template <class Offset = std::uint64_t, class Count>
Buffer<Offset> block_offsets(std::size_t n, Count&& count, Offset start = 0) {
  constexpr std::size_t kBlock = 1 << 14;
  const std::size_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<Offset> block_start(blocks + 1, 0);
  block_start[0] = start;
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    Offset sum = 0;
    for (std::size_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
      sum += static_cast<Offset>(count(i));
    }
    block_start[b + 1] = sum;
  });
  for (std::size_t b = 0; b < blocks; ++b) block_start[b + 1] += block_start[b];
  Buffer<Offset> offsets(n + 1);  // every element written below
  offsets[n] = block_start[blocks];
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    Offset at = block_start[b];
    for (std::size_t i = b * kBlock; i < std::min(n, (b + 1) * kBlock); ++i) {
      offsets[i] = at;
      at += static_cast<Offset>(count(i));
    }
  });
  return offsets;
}

}  // namespace ncv
