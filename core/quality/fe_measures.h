// The finite-element view of a mesh's quality (issue 16): the global explicit time step of P1
// elements with lumped mass (explicit_time_step.h), the per-element bound explicit codes use
// (the minimum of element_time_step.h over the elements, a lower bound of the global step), and
// the solver cost: Jacobi-CG iterations and the condition estimate of the P1 Poisson stiffness
// with the boundary as Dirichlet (poisson_cg.h). Wave speed c: both steps scale as 1/c.
// JSON keys time_step, element_time_step, cg_iterations, stiffness_condition (quality_table.h).
#pragma once
#include <string>

#include "core/mesh/tet_mesh.h"
#include "core/mesh/tri_mesh2.h"
#include "core/quality/quality_stats.h"

namespace cvtmesh {

// "auto" measures meshes of at most kFeMeasuresAutoLimit elements (the cost is a few times that
// of the quality table: docs/benchmarks.md), "on" any mesh, "off" none.
constexpr long kFeMeasuresAutoLimit = 1000000;

struct FeOptions {
  std::string mode = "auto";      // auto, on, off (std::invalid_argument otherwise)
  double wave_speed = 1;          // > 0
  double eigen_tolerance = 1e-3;  // relative, on lambda_max
  double cg_tolerance = 1e-8;     // relative residual
};

struct FeMeasures {
  bool measured = false;
  std::string skipped;  // why not measured ("" when measured)
  double time_step = 0, element_time_step = 0;
  long cg_iterations = 0;
  double stiffness_condition = 0;
  int lanczos_iterations = 0;
  bool converged = false;  // both Lanczos and CG reached their tolerances
  double seconds = 0;
};

FeMeasures fe_measures(const TetMesh& mesh, const FeOptions& options = {});
FeMeasures fe_measures(const TriMesh2& mesh, const FeOptions& options = {});

// Copies m into s's FE fields (s.fe_measured = m.measured).
void set_fe_measures(QualityStats& s, const FeMeasures& m);

}  // namespace cvtmesh
