// The number of OpenMP threads cvtmesh's parallel loops use, independent of what a library in the
// same process set. Gmsh sets its General.NumThreads (we keep it at 1 for reproducible meshing)
// with omp_set_num_threads, which is process-wide: after reading a mesh through Gmsh every
// parallel loop of ours would run on one thread. ThreadCountScope sets our count for the duration
// of an operation and gives the host (Gmsh's GUI, a Python script) its own count back afterwards.
#pragma once

namespace cvtmesh {

// OMP_NUM_THREADS if set (a positive integer), else the number of processors; decided on the
// first call.
int default_thread_count();

class ThreadCountScope {
 public:
  ThreadCountScope();
  ~ThreadCountScope();
  ThreadCountScope(const ThreadCountScope&) = delete;
  ThreadCountScope& operator=(const ThreadCountScope&) = delete;

 private:
  int previous_;
};

}  // namespace cvtmesh
