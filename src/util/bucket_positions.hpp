// A stable counting sort whose items come in a fixed number of chunks, run chunk by chunk side
// by side: each chunk counts its items per bucket, then each item is placed after the earlier
// chunks' items of its bucket and its own chunk's earlier ones, so every bucket keeps the
// items' order whatever the threads. The edge incidence's slots by lower vertex and the grid's
// references by cell are sorted so.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "util/block_offsets.hpp"
#include "util/buffer.hpp"

namespace ncv {

template <class Offset, std::size_t Chunks>
class BucketPositions {
 public:
  // for_each(c, emit) calls emit(bucket) for every item of chunk c, in the items' order. A
  // bucket holds fewer than 2^32 items of a chunk.
  template <class ForEach>
  BucketPositions(std::size_t buckets, ForEach&& for_each) {
    tbb::parallel_for(std::size_t{0}, Chunks, [&](std::size_t c) {
      cursor_[c].assign(buckets, 0);
      for_each(c, [&](std::size_t bucket) { ++cursor_[c][bucket]; });
    });
    starts_ = block_offsets<Offset>(buckets, [&](std::size_t bucket) {
      Offset count = 0;
      for (const auto& counts : cursor_) count += counts[bucket];
      return count;
    });
    // Each chunk's count becomes where its items start within the bucket.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, buckets, 1 << 14), [&](const auto& r) {
      for (std::size_t bucket = r.begin(); bucket != r.end(); ++bucket) {
        std::uint32_t next = 0;
        for (auto& counts : cursor_) next += std::exchange(counts[bucket], next);
      }
    });
  }

  // Where each bucket starts, and the item count last.
  const Buffer<Offset>& starts() const { return starts_; }
  Buffer<Offset> take_starts() { return std::move(starts_); }

  // The place of chunk c's next item in `bucket`: asked for chunk c's items in for_each's
  // order; chunks may ask side by side.
  Offset next(std::size_t c, std::size_t bucket) {
    return starts_[bucket] + static_cast<Offset>(cursor_[c][bucket]++);
  }

 private:
  std::array<Buffer<std::uint32_t>, Chunks> cursor_;
  Buffer<Offset> starts_;
};

}  // namespace ncv
