// Laplacian smoothing of the interior vertices (Du & Wang, Section 2: P_new = the mean of the
// vertices adjacent to P), guarded: a move that would invert a tet of the vertex's star (exact
// orient3d) or lower the minimum quality over the star is rejected, after trying half the step.
// Boundary, curve and corner vertices (vclass.dim < 3) never move; connectivity never changes.
#pragma once
#include "core/mesh/tet_mesh.h"
#include "core/quality/quality.h"
#include "core/quality/time_step_guard.h"

namespace cvtmesh {

struct SmoothOptions {
  // Gauss-Seidel sweeps over the interior vertices, colour by colour (a greedy colouring in vertex
  // order: no two vertices of a colour share a tet, so each colour moves in parallel; the result
  // does not depend on the number of threads).
  int passes = 1;
  // Larger-is-better measure of the local-minimum guard: kQ (default), kMinAngle, kRadiusRatio,
  // kGmshIcn. kMaxAngle throws std::invalid_argument.
  Measure measure = Measure::kQ;
  bool half_step = true;  // try P + (P_new - P)/2 when the full step is rejected
  // The time-step guard (time_step_guard.h; off by default): a move is also refused when the
  // star's smallest element time step falls below min(its value before the move, floor).
  TimeStepGuard dt_guard;
};

struct SmoothStats {
  int passes = 0;
  long nb_moved = 0;                     // full steps taken
  long nb_half = 0;                      // half steps taken
  long nb_rejected = 0;                  // vertices left in place
  double min_before = 0, min_after = 0;  // global minimum quality in options.measure
};

// Smooths mesh.xyz in place. The global minimum quality in options.measure never decreases.
// Dead tets are ignored; mesh.adj is not needed.
SmoothStats smooth_laplacian(TetMesh& mesh, const SmoothOptions& options = {});

}  // namespace cvtmesh
