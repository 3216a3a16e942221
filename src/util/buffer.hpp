// Buffer<T>: a std::vector whose resize leaves new elements unwritten, for large outputs
// that a parallel loop fills completely. Value-initialising them first would be a serial
// pass over the whole array in the calling thread (about 20 ms for the distance step's
// 46 MB at the paper's scale, one tenth of the step), and the page faults of first touch
// would all land on that thread instead of being spread over the workers.
//
// Large buffers (4 MiB and up) are aligned to 2 MiB and offered to the kernel for
// transparent huge pages (madvise; Linux's default THP mode): first touch then faults once
// per 2 MiB instead of once per 4 KiB, which for the distance step's buffers was a tenth of
// its time. Where huge pages are unavailable the advice is ignored. A freed large buffer is
// kept, its pages resident, for the next one it can hold (util/buffer.cpp): the kernel
// clears every fresh page at first touch, and a run's phases free and ask for buffers of
// about the same sizes; kept buffers are released before fresh pages are mapped, so the
// peak memory is no higher for them.
//
// Only for implicit-lifetime element types (trivially copyable, trivially destructible):
// the allocation itself creates their objects, so skipping the constructor is well defined;
// their values are indeterminate until written, and every user writes each element before
// reading it.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <limits>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace ncv {

namespace detail {
inline constexpr std::size_t kHugePage = std::size_t{2} << 20;
inline constexpr std::size_t kHugeBufferBytes = std::size_t{4} << 20;
void* allocate_huge(std::size_t bytes);               // aligned to kHugePage; throws std::bad_alloc
void free_huge(void* p, std::size_t bytes) noexcept;  // bytes: as allocated
}  // namespace detail

template <class T>
class UninitializedAllocator : public std::allocator<T> {
 public:
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
    if (n * sizeof(T) < detail::kHugeBufferBytes) return std::allocator<T>{}.allocate(n);
    return static_cast<T*>(detail::allocate_huge(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < detail::kHugeBufferBytes) return std::allocator<T>{}.deallocate(p, n);
    detail::free_huge(p, n * sizeof(T));
  }

  template <class U>
  void construct(U*) noexcept {
    static_assert(std::is_trivially_copyable_v<U> && std::is_trivially_destructible_v<U>);
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T>
using Buffer = std::vector<T, UninitializedAllocator<T>>;

// Unmaps the largest of the freed buffers kept so far until the others hold at most
// keep_bytes. A buffer asking for fresh pages takes or releases them all itself; this is for a
// program whose large buffers are made, so that the kept ones do not stay resident under the
// allocations that follow, bar a few for the small buffers still to come.
void release_kept_buffers(std::size_t keep_bytes) noexcept;

}  // namespace ncv
