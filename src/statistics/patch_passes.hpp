// Passes over a PatchSource: in fixed blocks in parallel, each block's result combined in
// block order (so that sums do not depend on the thread count), or in index order on one
// thread. Patches made on demand are made into a per-thread scratch array, reused from one
// block to the next, so a pass touches no fresh memory.
#pragma once

#include <algorithm>
#include <cstddef>
#include <functional>
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

// The sum of term(p) over patches fed a range at a time in index order, however the ranges
// are cut: each block of kPatchBlock patches summed from zero, the blocks' sums added in
// order, which is reduce_patch_blocks' sum of the same terms, to the bit. A serial pass can
// so make a parallel pass's sum without a pass of its own.
template <class Term>
class OrderedPatchSum {
 public:
  explicit OrderedPatchSum(Term term) : term_(std::move(term)) {}

  void add(std::span<const LinearPatch> range) {
    while (!range.empty()) {
      if (position_ % kPatchBlock == 0 && position_ > 0) {
        total_ += block_;
        block_ = 0;
      }
      const std::size_t n = std::min(range.size(), kPatchBlock - position_ % kPatchBlock);
      for (const LinearPatch& p : range.first(n)) block_ += term_(p);
      position_ += n;
      range = range.subspan(n);
    }
  }

  // The last block is still open: a block is added when the next one starts.
  double sum() const { return position_ > 0 ? total_ + block_ : 0.0; }

 private:
  Term term_;
  std::size_t position_ = 0;
  double block_ = 0;
  double total_ = 0;
};

// A consumer of every patch once, a range at a time in index order, on one thread: a serial
// pass that another pass over the same patches can carry along instead of making them again.
using PatchRangeVisitor = std::function<void(std::span<const LinearPatch>)>;

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
