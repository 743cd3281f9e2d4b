// OpenMP's idle threads of our programs (the CLI, cvtmesh-mpi, the GUI, the ONELAB solver,
// the test runner): passive (asleep) rather than spinning.
//
// libgomp reads OMP_WAIT_POLICY when it is loaded, before main. Its default spins each idle
// thread for a while after every parallel region; the pipeline alternates parallel loops with
// serial work (the polish, the sliver repair), so on a busy machine (another process, or the
// ranks of `mpirun -n 2 cvtmesh-mpi` on 2 cores) the spinning threads take the cores from the
// serial work: igl_decimated-knight's default run took 49 s instead of 4 s beside two busy
// processes, 5.9 s with OMP_WAIT_POLICY=passive (docs/benchmarks.md, "Idle OpenMP threads").
#pragma once

namespace cvtmesh {

// When neither OMP_WAIT_POLICY nor GOMP_SPINCOUNT is set, sets OMP_WAIT_POLICY=passive and runs
// this program again with the same arguments (execv of the file /proc/self/exe names); returns (and
// the program goes on as it is) when either is set or the new image cannot be started. Call it
// first in main, before MPI_Init or any thread.
void prefer_passive_openmp_threads(char** argv);

}  // namespace cvtmesh
