// Buffer: large buffers at huge-page boundaries, a freed one kept for the next it can hold,
// and never one block handed to two buffers at once.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <numeric>

#include <tbb/parallel_for.h>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "util/buffer.hpp"

using namespace ncv;

namespace {

constexpr std::size_t kMiB = std::size_t{1} << 20;

std::uintptr_t address(const Buffer<std::uint32_t>& buffer) {
  return reinterpret_cast<std::uintptr_t>(buffer.data());
}

}  // namespace

TEST_CASE("large buffers start at a huge-page boundary and hold what is written", "[buffer]") {
  for (const std::size_t bytes : {4 * kMiB, 4 * kMiB + 4, 9 * kMiB, 33 * kMiB + 12}) {
    Buffer<std::uint32_t> buffer(bytes / 4);
    CHECK(address(buffer) % detail::kHugePage == 0);
    std::iota(buffer.begin(), buffer.end(), 7u);
    CHECK(buffer.front() == 7u);
    CHECK(buffer.back() == 7u + buffer.size() - 1);
  }
}

#if defined(__linux__) && !defined(__SANITIZE_ADDRESS__)
TEST_CASE("a freed large buffer is reused by the next one it can hold", "[buffer]") {
  // A buffer larger than any kept one takes them all (it fits none), so that what follows
  // sees only the blocks it frees itself, whatever ran before; released at once.
  { const Buffer<char> larger_than_any(std::size_t{1} << 30); }
  release_kept_buffers(0);
  std::uintptr_t freed = 0;
  {
    Buffer<std::uint32_t> first(24 * kMiB / 4);
    first.back() = 1;
    freed = address(first);
  }
  Buffer<std::uint32_t> smaller(10 * kMiB / 4);
  CHECK(address(smaller) == freed);
  std::fill(smaller.begin(), smaller.end(), 3u);
  CHECK(smaller.back() == 3u);
}

// Whether the page at `at` is mapped: mincore fails with ENOMEM where nothing is.
bool mapped(std::uintptr_t at) {
  unsigned char resident = 0;
  return mincore(reinterpret_cast<void*>(at), 4096, &resident) == 0;
}

TEST_CASE("a buffer that fits no kept one is made of them, the largest first", "[buffer]") {
  release_kept_buffers(0);
  {
    Buffer<std::uint32_t> a(6 * kMiB / 4);
    std::fill(a.begin(), a.end(), 0xaaaau);
    Buffer<std::uint32_t> b(10 * kMiB / 4);
    std::fill(b.begin(), b.end(), 0xbbbbu);
  }
  // 24 MiB: b's pages first, then a's, then fresh (zero) ones; none of them copied.
  const Buffer<std::uint32_t> c(24 * kMiB / 4);
  const std::size_t a_begin = 10 * kMiB / 4, fresh_begin = 16 * kMiB / 4;
  CHECK(std::all_of(c.begin(), c.begin() + a_begin, [](std::uint32_t w) { return w == 0xbbbbu; }));
  CHECK(std::all_of(c.begin() + a_begin, c.begin() + fresh_begin,
                    [](std::uint32_t w) { return w == 0xaaaau; }));
  CHECK(std::all_of(c.begin() + fresh_begin, c.end(), [](std::uint32_t w) { return w == 0; }));
}

TEST_CASE("releasing the kept buffers keeps the smallest within the budget", "[buffer]") {
  release_kept_buffers(0);
  std::uintptr_t small = 0, large = 0;
  {
    Buffer<std::uint32_t> a(8 * kMiB / 4);
    a.back() = 1;
    small = address(a);
    Buffer<std::uint32_t> b(32 * kMiB / 4);
    b.back() = 1;
    large = address(b);
  }
  release_kept_buffers(16 * kMiB);
  CHECK(mapped(small));
  CHECK_FALSE(mapped(large));
  const Buffer<std::uint32_t> again(6 * kMiB / 4);
  CHECK(address(again) == small);
  release_kept_buffers(0);
}
#endif

TEST_CASE("buffers allocated and freed side by side never share memory", "[buffer]") {
  // Each task fills its buffer with its own number, then checks it is still there: two
  // buffers given the same block would see each other's writes.
  std::atomic<int> corrupted{0};
  tbb::parallel_for(0, 64, [&](int task) {
    const std::size_t words = (4 * kMiB + static_cast<std::size_t>(task % 5) * kMiB) / 4;
    Buffer<std::uint32_t> buffer(words);
    std::fill(buffer.begin(), buffer.end(), static_cast<std::uint32_t>(task));
    for (int round = 0; round < 3; ++round) {
      Buffer<std::uint32_t> scratch(words / 2 + 1);
      std::fill(scratch.begin(), scratch.end(), ~static_cast<std::uint32_t>(task));
    }
    if (std::count(buffer.begin(), buffer.end(), static_cast<std::uint32_t>(task)) !=
        static_cast<std::ptrdiff_t>(words)) {
      ++corrupted;
    }
  });
  CHECK(corrupted == 0);
}
