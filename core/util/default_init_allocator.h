// An allocator whose value construction leaves trivial elements uninitialized: resize() then
// writes nothing, and the pages of a fresh buffer are first touched where the elements are first
// written (e.g. by the threads of a parallel loop) instead of being zeroed by one thread first.
#pragma once
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace cvtmesh {

template <class T, class A = std::allocator<T>>
class DefaultInitAllocator : public A {
  using Traits = std::allocator_traits<A>;

 public:
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U, typename Traits::template rebind_alloc<U>>;
  };
  using A::A;

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    Traits::construct(static_cast<A&>(*this), p, std::forward<Args>(args)...);
  }
};

}  // namespace cvtmesh
