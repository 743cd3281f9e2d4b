// Two independent computations of the same kind (a check's pass over the mesh before and the mesh
// after an operation) on two OpenMP threads at once, each run whole by one thread: the values are
// those of f(a) then f(b) one after the other, for any number of threads (one thread: in that
// order). An exception from either is rethrown after both ended (f(a)'s first), never out of the
// parallel region. Inside f, nested parallel loops run on the thread that runs f.
#pragma once
#include <exception>
#include <utility>

namespace cvtmesh {

template <class A, class B, class F>
auto on_both(const A& a, const B& b, F f) -> std::pair<decltype(f(a)), decltype(f(b))> {
  std::pair<decltype(f(a)), decltype(f(b))> r;
  std::exception_ptr error[2];
#pragma omp parallel sections num_threads(2)
  {
#pragma omp section
    {
      try {
        r.first = f(a);
      } catch (...) {
        error[0] = std::current_exception();
      }
    }
#pragma omp section
    {
      try {
        r.second = f(b);
      } catch (...) {
        error[1] = std::current_exception();
      }
    }
  }
  for (const std::exception_ptr& e : error)
    if (e) std::rethrow_exception(e);
  return r;
}

}  // namespace cvtmesh
