// Buffer<T>: a std::vector whose resize() leaves trivially constructible elements
// uninitialised, for large arrays that are filled right after (mesh vertex arrays: zeroing
// 23 MB of a pine's leaf cards before overwriting them cost a fifth of its mesh time).
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace eco {

template <typename T, typename Base = std::allocator<T>>
class DefaultInitAllocator : public Base {
 public:
  template <typename U>
  struct rebind {
    using other =
        DefaultInitAllocator<U, typename std::allocator_traits<Base>::template rebind_alloc<U>>;
  };
  using Base::Base;

  // Value-initialisation (what resize() asks for) becomes default-initialisation.
  template <typename U>
  void construct(U* place) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(place)) U;
  }
  template <typename U, typename... Args>
  void construct(U* place, Args&&... args) {
    std::allocator_traits<Base>::construct(static_cast<Base&>(*this), place,
                                           std::forward<Args>(args)...);
  }
};

template <typename T>
using Buffer = std::vector<T, DefaultInitAllocator<T>>;

// Makes a working array (kept from one use to the next, each element written before it is
// read) hold n elements, its old values not kept. Where n passes its capacity, the old storage
// is freed before the new is taken, where resize() copies the old into the new and holds both:
// at a landscape's scale a working array is a gigabyte, and a year whose crowns were a few
// more than the last's held the two together at the run's peak. The new storage has a quarter
// more room, so a count that grows a little each year does not take new storage each year.
template <typename T, typename A>
void resizeForOverwrite(std::vector<T, A>& array, std::size_t n) {
  if (n > array.capacity()) {
    std::vector<T, A>().swap(array);
    array.reserve(n + n / 4);
  }
  array.resize(n);
}

}  // namespace eco
