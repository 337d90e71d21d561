#pragma once
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace rtvk {

// A std::allocator whose resize() leaves new elements default-initialized (for plain structs:
// uninitialized) instead of zeroed: for large arrays that are then written whole, in parallel,
// so the pages are first touched by the threads that fill them rather than zeroed by one thread.
template <typename T>
struct uninitialized_allocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = uninitialized_allocator<U>;
  };
  uninitialized_allocator() = default;
  template <typename U>
  uninitialized_allocator(const uninitialized_allocator<U>&) noexcept {}

  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <typename T>
using uninitialized_vector = std::vector<T, uninitialized_allocator<T>>;

}  // namespace rtvk
