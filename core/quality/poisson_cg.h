// The solver cost of a mesh: Jacobi-preconditioned conjugate gradients on the P1 Poisson problem
// -Lap u = 1 with u = 0 on the domain boundary (P1System::boundary vertices, and those of no
// element, are Dirichlet). Right-hand side: the lumped load b_i = mass_i (f = 1) on the free
// vertices; start x = 0; stop when ||b - K x||_2 <= tolerance ||b||_2 (the true residual is
// recomputed at the stop). The condition estimate is that of the preconditioned matrix D^-1 K
// on the free vertices (D = diag K): the ratio of the extreme eigenvalues of the Lanczos
// tridiagonal matrix CG builds from its coefficients, which governs the iteration count.
#pragma once
#include <vector>

#include "core/quality/p1_system.h"

namespace cvtmesh {

struct PoissonCg {
  int iterations = 0;      // CG iterations to the tolerance (0: no free vertex)
  bool converged = false;  // reached the tolerance within max_iterations
  double residual = 0;     // ||b - K x|| / ||b|| at the end (recomputed, not the recurrence)
  double condition = 0;    // estimate of cond(D^-1 K) on the free vertices
  std::vector<double> x;   // the solution (n values, 0 on the Dirichlet vertices)
};

PoissonCg poisson_cg(const P1System& system, double tolerance = 1e-8, int max_iterations = 20000);

}  // namespace cvtmesh
