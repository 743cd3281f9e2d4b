#include "core/pipeline/combined_optimize.h"

#include <algorithm>
#include <stdexcept>

#include "core/mesh/build_adjacency.h"
#include "core/quality/time_step_guard.h"

namespace cvtmesh {

CombinedStats combined_optimize(TetMesh& mesh, const CombinedOptions& options,
                                std::function<void(int iteration, const QualityStats&)> progress) {
  if (options.max_iterations < 0)
    throw std::invalid_argument("combined_optimize: max_iterations must be >= 0");
  if (options.smoothing_passes < 0)
    throw std::invalid_argument("combined_optimize: smoothing_passes must be >= 0");
  if (mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);
  CombinedStats stats;
  stats.before = quality_stats(mesh, "Init");
  QualityStats prev = stats.before;
  SmoothOptions smooth = options.smoothing;
  smooth.passes = options.smoothing_passes;
  SwapOptions swap = options.swap;
  swap.compact = true;
  MaxMinOptions maxmin = options.maxmin_options;
  for (int it = 1; it <= options.max_iterations; ++it) {
    if (options.dt_guard_factor > 0)
      smooth.dt_guard = maxmin.dt_guard = swap.dt_guard =
          time_step_guard(mesh, options.dt_guard_factor);
    const SmoothStats ss = smooth_laplacian(mesh, smooth);
    if (options.maxmin) stats.nb_maxmin_moved += smooth_maxmin3(mesh, maxmin).nb_moved;
    if (options.extra_smoothing) stats.nb_maxmin_moved += options.extra_smoothing(mesh);
    if (options.keep_min_q)
      swap.guard_floor = std::max(options.swap.guard_floor, min_quality(mesh, Measure::kQ));
    const SwapStats sw = swap_slivers(mesh, swap);
    stats.nb_moved += ss.nb_moved + ss.nb_half;
    stats.nb_flips += sw.nb_flip23 + sw.nb_flip32 + sw.nb_edge_removals;
    stats.iterations = it;
    const QualityStats now = quality_stats(mesh, "CombOpt");
    if (progress) progress(it, now);
    const double avg_tolerance =
        options.average_tolerance >= 0 ? options.average_tolerance : options.tolerance;
    const bool targets_met = options.stop_at_maxmin_targets &&
                             now.q_min >= options.maxmin_options.q_below &&
                             now.min_angle >= options.maxmin_options.angle_below;
    const bool improved =
        now.q_avg > prev.q_avg + avg_tolerance ||
        (!targets_met && (now.q_min > prev.q_min + options.tolerance ||
                          now.min_angle > prev.min_angle + options.angle_tolerance));
    prev = now;
    if (!improved) {
      stats.converged = true;
      break;
    }
  }
  // The last iteration's figures are the mesh's (nothing changed it since).
  stats.after = stats.iterations > 0 ? prev : quality_stats(mesh, "CombOpt");
  return stats;
}

}  // namespace cvtmesh
