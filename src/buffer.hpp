// Buffer<T>: a std::vector whose resize leaves new elements unwritten, for large outputs
// that a parallel loop fills completely. Value-initialising them first would be a serial
// pass over the whole array in the calling thread (about 20 ms for the distance step's
// 46 MB at the paper's scale, one tenth of the step), and the page faults of first touch
// would all land on that thread instead of being spread over the workers.
//
// Only for implicit-lifetime element types (trivially copyable, trivially destructible):
// the allocation itself creates their objects, so skipping the constructor is well defined;
// their values are indeterminate until written, and every user writes each element before
// reading it.
#pragma once

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace ncv {

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

}  // namespace ncv
