// Passes over a PatchSource: in fixed blocks in parallel, each block's result combined in
// block order (so that sums do not depend on the thread count), or in index order on one
// thread. Patches made on demand are made into a per-thread scratch array, reused from one
// block to the next, so a pass touches no fresh memory.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <utility>

#include "geometry/patch_source.hpp"
#include "util/ordered_reduce.hpp"

namespace ncv {

// The block of every parallel pass over patches: a block's partial sums depend on where the
// blocks start, so every measure reduces in these.
inline constexpr std::size_t kPatchBlock = std::size_t{1} << 16;

// This thread's scratch array, at least `count` patches long (its contents unspecified).
std::span<LinearPatch> patch_scratch(std::size_t count);

// reduce_block(patches) for each block of kPatchBlock patches, combined in block order.
template <class T, class ReduceBlock, class Combine>
T reduce_patch_blocks(const PatchSource& source, T identity, ReduceBlock&& reduce_block,
                      Combine&& combine) {
  return ordered_reduce(
      source.size(), kPatchBlock, std::move(identity),
      [&](std::size_t begin, std::size_t end) {
        return reduce_block(source.range(begin, end, patch_scratch(end - begin)));
      },
      combine);
}

// visit(patches) for consecutive ranges covering all patches, in index order, on this thread.
template <class Visit>
void for_each_patch_range(const PatchSource& source, Visit&& visit) {
  constexpr std::size_t kRange = std::size_t{1} << 13;  // 256 kB of patches: in cache
  for (std::size_t begin = 0; begin < source.size(); begin += kRange) {
    const std::size_t end = std::min(source.size(), begin + kRange);
    visit(source.range(begin, end, patch_scratch(end - begin)));
  }
}

}  // namespace ncv
