// The classical "Combined Optimization" (Du & Wang, Section 4, the CombOpt column of Tables 6
// and 7): each iteration runs 3-5 guarded Laplacian smoothing passes over the interior vertices,
// then edge/face flips that improve the minimal dihedral angles (swap_slivers with kMinAngle);
// iterations stop when the quality stops improving or at max_iterations. Optionally (the
// pipeline's polish) each iteration also runs the max-min smoothing of the poor tets
// (smooth_maxmin3) between the Laplacian passes and the flips.
#pragma once
#include <functional>

#include "core/mesh/tet_mesh.h"
#include "core/quality/quality_stats.h"
#include "core/smoothing/smooth_laplacian.h"
#include "core/smoothing/smooth_maxmin3.h"
#include "core/swap/swap_slivers.h"

namespace cvtmesh {

struct CombinedOptions {
  int max_iterations = 20;
  int smoothing_passes = 3;  // Laplacian passes per iteration (the paper: three to five)
  SmoothOptions smoothing;   // its `passes` is ignored (smoothing_passes is used)
  // Max-min smoothing of the poor tets' vertices (smooth_maxmin3) after the Laplacian passes of
  // each iteration (off in the classical CombOpt).
  bool maxmin = false;
  MaxMinOptions maxmin_options;
  // Called after the max-min smoothing of each iteration (the pipeline's boundary max-min when
  // the boundary is free); returns the number of changes it made. Must leave the mesh valid,
  // its tets compacted and its adjacency built (it may flip).
  std::function<long(TetMesh&)> extra_smoothing;
  // Raise the flips' guard floor (swap.guard_floor, with swap.use_guard) to the mesh's current
  // minimum Q before each iteration's flips, so that they never lower the global minimum Q.
  bool keep_min_q = false;
  // The time-step guard (core/quality/time_step_guard.h) of the smoothing, max-min and flips:
  // 0 = off; otherwise before each iteration its floor is this factor times the mesh's smallest
  // element time step (+inf: no star's or ring's smallest step may fall at all).
  double dt_guard_factor = 0;
  SwapOptions swap = [] {
    SwapOptions s;
    s.measure = Measure::kMinAngle;  // flips improving the minimal dihedral angles
    return s;
  }();
  // Converged when an iteration raises neither the average Q nor the minimum Q by more than
  // `tolerance`, nor the minimum dihedral angle by more than `angle_tolerance` degrees.
  double tolerance = 1e-4;
  double angle_tolerance = 1e-2;
  // The average's own tolerance where it differs (-1: `tolerance`). The polish uses 5e-4: its
  // last iterations raise the average by 1e-4 to 4e-4 and nothing else, for a fifth of its time
  // each (cube_sphere 25k: 6 iterations -> 4, avg 0.86126 -> 0.86111; 100k: 5 -> 4).
  double average_tolerance = -1;
  // Once an iteration ends with the max-min's targets reached (the minimum Q at least
  // maxmin_options.q_below, the minimum dihedral angle at least its angle_below: no poor tet
  // left for it), gains in the minima no longer count, only the average's. The free-boundary
  // polish sets it: the average-quality passes that follow raise the average faster.
  bool stop_at_maxmin_targets = false;
};

struct CombinedStats {
  int iterations = 0;
  bool converged = false;
  QualityStats before, after;
  long nb_moved = 0;         // accepted vertex moves (full or half steps), all iterations
  long nb_flips = 0;         // committed flips and edge removals, all iterations
  long nb_maxmin_moved = 0;  // vertices moved by the max-min smoothing, all iterations
};

// Optimizes mesh in place (vertices with vclass.dim < 3 never move, constrained faces are kept,
// no tet is ever inverted). progress(iteration, stats) is called after each iteration with the
// quality statistics of the mesh at that point. Builds mesh.adj if needed; leaves it valid and
// the tets compacted. Throws std::invalid_argument for bad options.
CombinedStats combined_optimize(
    TetMesh& mesh, const CombinedOptions& options = {},
    std::function<void(int iteration, const QualityStats&)> progress = nullptr);

}  // namespace cvtmesh
