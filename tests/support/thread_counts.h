#pragma once
// The "same result for any number of threads" tests' loop: run the same computation with the
// process's OpenMP thread count set to each of a few counts, the caller's count restored after
// (also when a run throws).

#include <omp.h>

#include <initializer_list>
#include <type_traits>
#include <vector>

namespace cvtmesh::testing {

// Restores the process's OpenMP thread count on scope exit.
class ThreadCountGuard {
 public:
  ThreadCountGuard() : saved_(omp_get_max_threads()) {}
  ~ThreadCountGuard() { omp_set_num_threads(saved_); }
  ThreadCountGuard(const ThreadCountGuard&) = delete;
  ThreadCountGuard& operator=(const ThreadCountGuard&) = delete;

 private:
  int saved_;
};

// run() once per count (1, 2, 3 by default: one thread, the machine's two, one more than there
// are cores), each on that many threads; the results in the order of the counts.
template <class Run>
auto for_each_thread_count(Run&& run, std::initializer_list<int> counts = {1, 2, 3}) {
  std::vector<std::invoke_result_t<Run&>> results;
  ThreadCountGuard guard;
  for (int threads : counts) {
    omp_set_num_threads(threads);
    results.push_back(run());
  }
  return results;
}

}  // namespace cvtmesh::testing
