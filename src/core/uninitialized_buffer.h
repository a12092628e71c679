#pragma once
// std::vector whose resize leaves trivially constructible elements uninitialised: the renderer's
// caches are fully overwritten by the stage that fills them, so zeroing them first would only
// cost a memory pass (measured: about 8% of a 1280x720 render in page clearing and memset).
#include <memory>
#include <new>
#include <vector>

namespace gloss {

template <class T>
struct DefaultInitAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U>;
  };
  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept(noexcept(::new (static_cast<void*>(p)) U)) {
    ::new (static_cast<void*>(p)) U;  // default-, not value-initialisation
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

template <class T>
using UninitializedBuffer = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace gloss
