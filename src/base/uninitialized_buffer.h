#pragma once
// std::vector whose resize leaves trivially constructible elements uninitialised: the renderer's
// caches are fully overwritten by the stage that fills them, so zeroing them first would only
// cost a memory pass, a measurable share of a render (docs/engine.md, "Uninitialised caches").
// Storage is aligned to 64-byte cache lines, so packets can stream whole lines into it.
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
  static constexpr std::align_val_t kAlignment{64};

  DefaultInitAllocator() = default;
  template <class U>
  DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
  T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kAlignment)); }
  void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, kAlignment); }
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
