#include "core/util/thread_count.h"

#include <omp.h>

#include <cstdlib>

namespace cvtmesh {

int default_thread_count() {
  static const int n = [] {
    if (const char* env = std::getenv("OMP_NUM_THREADS")) {
      char* end = nullptr;
      const long v = std::strtol(env, &end, 10);
      if (end != env && v > 0 && v < 4096) return static_cast<int>(v);
    }
    return omp_get_num_procs();
  }();
  return n;
}

ThreadCountScope::ThreadCountScope() : previous_(omp_get_max_threads()) {
  omp_set_num_threads(default_thread_count());
}

ThreadCountScope::~ThreadCountScope() {
  omp_set_num_threads(previous_);
}

}  // namespace cvtmesh
