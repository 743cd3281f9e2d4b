// The Lloyd iteration (Du & Wang, Algorithm 2.1), one loop for both dimensions.
// A Problem moves its free generators to the mass centroids of their (clipped) Voronoi cells and
// re-inserts them into the constrained boundary Delaunay triangulation; the loop only decides
// when to stop (D below tolerance, or max iterations) and reports progress.
#pragma once
#include <functional>
#include <vector>

namespace cvtmesh {

struct LloydOptions {
  int max_iterations = 100;
  // Stop when D = (1/k) sum_i |P_i - P*_i|^2 / h_i^2 (the paper's D, normalised by the local size
  // h_i and the number k of free vertices: the mean squared relative move) is below this.
  double tolerance = 1e-5;
};

// What one Lloyd iteration reports.
struct LloydStep {
  int iteration = 0;
  // 2D basin hopping: the trial this step belongs to (0 = the first minimiser run).
  int hop = 0;
  double D = 0;            // normalised displacement to the centroids (see LloydOptions)
  double energy = 0;       // CVT energy F = sum_i int_{V_i} rho |x - z_i|^2 before the move
  int nb_free = 0;         // generators allowed to move
  int nb_limited = 0;      // moves shortened by a safeguard (target outside the domain, ...)
  bool restarted = false;  // an accelerated step was rejected (energy rose): plain step taken
  // Where the time went (wall seconds; 0 where a dimension does not measure it) and how the
  // cells were computed (3D: exact Delaunay dual vs clipped by the bisectors).
  double seconds_cells = 0, seconds_move = 0, seconds_delaunay = 0, seconds_check = 0;
  int nb_dual_cells = 0, nb_clipped_cells = 0;
  // 3D re-insertion: flips that restored the Delaunay property, or a full rebuild.
  int nb_flips = 0;
  bool rebuilt = false;
  int nb_stuck_faces = 0, nb_short_moves = 0;  // left by the flips (see Lloyd3Options)
};

struct LloydResult {
  int iterations = 0;
  bool converged = false;
  std::vector<LloydStep> history;
};

// Problem: `LloydStep step()` performs one iteration (centroids, move, re-triangulation) and
// returns its D and energy. The loop stops when D < tolerance after a step.
template <class Problem>
LloydResult lloyd_iterate(Problem& problem, const LloydOptions& options,
                          const std::function<void(const LloydStep&)>& progress = nullptr) {
  LloydResult r;
  for (int it = 1; it <= options.max_iterations; ++it) {
    LloydStep s = problem.step();
    s.iteration = it;
    r.history.push_back(s);
    r.iterations = it;
    if (progress) progress(s);
    if (s.D < options.tolerance) {
      r.converged = true;
      break;
    }
  }
  return r;
}

}  // namespace cvtmesh
