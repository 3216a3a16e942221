#include "util/buffer.hpp"

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

// Under AddressSanitizer the buffers come from its malloc, which guards their ends.
#if defined(__SANITIZE_ADDRESS__)
#define NCV_KEEP_FREED_BUFFERS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define NCV_KEEP_FREED_BUFFERS 0
#endif
#endif
#if !defined(NCV_KEEP_FREED_BUFFERS) && defined(__linux__)
#define NCV_KEEP_FREED_BUFFERS 1
#elif !defined(NCV_KEEP_FREED_BUFFERS)
#define NCV_KEEP_FREED_BUFFERS 0
#endif

namespace ncv::detail {
namespace {

std::size_t rounded_size(std::size_t bytes) {
  return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}

}  // namespace

#if NCV_KEEP_FREED_BUFFERS

namespace {

// Freed huge buffers, their pages still resident, kept for the next buffers that fit: a new
// buffer's first touch makes the kernel clear every page it faults in (13-16 % of a
// two-sided run's CPU), and a run frees buffers of one phase just before the next phase
// asks for buffers of about their size (the reverse search's boxes before the statistics'
// patches, the read file before the samples). A buffer that fits none of them is made of
// them, their pages moved in one after the other (fill), and fresh pages only for the rest;
// the blocks that no longer fit are released. Either way the process never holds more than
// it held before the buffers now cached were freed: the peak is no higher than without the
// cache.
class FreedBlocks {
 public:
  // The smallest kept block of at least `bytes`, its tail beyond them released; null when
  // none is that large.
  void* take(std::size_t bytes) {
    std::lock_guard lock(mutex_);
    auto best = blocks_.end();
    for (auto block = blocks_.begin(); block != blocks_.end(); ++block) {
      if (block->bytes >= bytes && (best == blocks_.end() || block->bytes < best->bytes)) {
        best = block;
      }
    }
    if (best == blocks_.end()) return nullptr;
    const Block block = *best;
    blocks_.erase(best);
    if (block.bytes > bytes) munmap(static_cast<char*>(block.start) + bytes, block.bytes - bytes);
    return block.start;
  }

  // Moves kept blocks, the largest first, into the fresh range [start, start + bytes) one
  // after the other (their pages with them: mremap moves the page tables, huge pages whole,
  // and copies nothing), so that only what they cannot fill is faulted in fresh; the blocks
  // that no longer fit are released. The process holds no more than before: every kept page
  // is moved or released. A block mremap cannot move is released, its part of the range
  // left fresh.
  void fill(char* start, std::size_t bytes) noexcept {
    std::lock_guard lock(mutex_);
    std::sort(blocks_.begin(), blocks_.end(),
              [](const Block& a, const Block& b) { return a.bytes > b.bytes; });
    std::size_t filled = 0;
    for (const Block& block : blocks_) {
      if (filled + block.bytes <= bytes &&
          mremap(block.start, block.bytes, block.bytes, MREMAP_MAYMOVE | MREMAP_FIXED,
                 start + filled) != MAP_FAILED) {
        filled += block.bytes;
      } else {
        munmap(block.start, block.bytes);
      }
    }
    blocks_.clear();
  }

  // Unmaps the largest kept blocks until the others hold at most `bytes`.
  void release_beyond(std::size_t bytes) noexcept {
    std::lock_guard lock(mutex_);
    std::sort(blocks_.begin(), blocks_.end(),
              [](const Block& a, const Block& b) { return a.bytes < b.bytes; });
    std::size_t kept = 0, count = 0;
    while (count < blocks_.size() && kept + blocks_[count].bytes <= bytes) {
      kept += blocks_[count++].bytes;
    }
    for (std::size_t k = count; k < blocks_.size(); ++k) {
      munmap(blocks_[k].start, blocks_[k].bytes);
    }
    blocks_.resize(count);
  }

  void keep(void* start, std::size_t bytes) noexcept {
    std::lock_guard lock(mutex_);
    try {
      blocks_.push_back({start, bytes});
    } catch (const std::bad_alloc&) {
      munmap(start, bytes);
    }
  }

 private:
  struct Block {
    void* start;
    std::size_t bytes;
  };
  std::mutex mutex_;
  std::vector<Block> blocks_;
};

FreedBlocks& freed_blocks() {
  static FreedBlocks* blocks = new FreedBlocks;  // never destroyed: buffers outlive statics
  return *blocks;
}

// Fresh pages at a huge-page boundary: mapped with a huge page's slack, the ends cut off.
void* map_fresh(std::size_t bytes) {
  void* mapped =
      mmap(nullptr, bytes + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (mapped == MAP_FAILED) throw std::bad_alloc();
  char* const base = static_cast<char*>(mapped);
  const std::size_t misalignment = reinterpret_cast<std::uintptr_t>(base) % kHugePage;
  const std::size_t head = misalignment == 0 ? 0 : kHugePage - misalignment;
  if (head > 0) munmap(base, head);
  munmap(base + head + bytes, kHugePage - head);
#if defined(MADV_HUGEPAGE)
  madvise(base + head, bytes, MADV_HUGEPAGE);  // advice only: failure leaves ordinary pages
#endif
  return base + head;
}

}  // namespace

void* allocate_huge(std::size_t bytes) {
  const std::size_t rounded = rounded_size(bytes);
  if (void* reused = freed_blocks().take(rounded)) return reused;
  void* fresh = map_fresh(rounded);
  freed_blocks().fill(static_cast<char*>(fresh), rounded);
  return fresh;
}

void free_huge(void* p, std::size_t bytes) noexcept {
  freed_blocks().keep(p, rounded_size(bytes));
}

#else

void* allocate_huge(std::size_t bytes) {
  const std::size_t rounded = rounded_size(bytes);
  void* p = std::aligned_alloc(kHugePage, rounded);
  if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  madvise(p, rounded, MADV_HUGEPAGE);  // advice only: failure leaves ordinary pages
#endif
  return p;
}

void free_huge(void* p, std::size_t) noexcept {
  std::free(p);
}

#endif

}  // namespace ncv::detail

namespace ncv {

void release_kept_buffers(std::size_t keep_bytes) noexcept {
#if NCV_KEEP_FREED_BUFFERS
  detail::freed_blocks().release_beyond(keep_bytes);
#else
  (void)keep_bytes;
#endif
}

}  // namespace ncv
