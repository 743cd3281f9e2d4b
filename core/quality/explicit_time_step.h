// The global explicit time step of a P1 mesh with row-sum lumped mass (central differences on
// u_tt = Lap u, wave speed 1): dt = 2 / sqrt(lambda_max(M_L^-1 K)), natural (free) boundary, the
// largest eigenvalue by Lanczos on the symmetric M_L^-1/2 K M_L^-1/2, from a fixed start vector
// (the result depends on the input only), no reorthogonalization (the largest Ritz value
// converges first), stopped when the Ritz residual bound beta_k |s_k| of the largest Ritz value
// is below rel_tolerance times it: lambda_max to rel_tolerance, dt to about half of it.
#pragma once
#include "core/quality/p1_system.h"

namespace cvtmesh {

struct ExplicitTimeStep {
  double lambda_max = 0;  // of M_L^-1 K
  double time_step = 0;   // 2 / sqrt(lambda_max); 0 for an empty system
  int iterations = 0;     // Lanczos steps (one product by K each)
  bool converged = false;
};

// Vertices with zero mass (in no element) are left out.
ExplicitTimeStep explicit_time_step(const P1System& system, double rel_tolerance = 1e-3,
                                    int max_iterations = 2000);

}  // namespace cvtmesh
