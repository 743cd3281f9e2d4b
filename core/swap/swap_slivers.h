// SWAP: sliver removal by topological operations only (Du & Wang, Section 4: "simple edge or
// face swappings"). Repeated passes over the tets, worst first; for each, every edge removal
// (ring of 3..7 tets, the 3-2 flip included) on its six edges and every 2-3 flip on its four
// faces is planned, and the best one the criterion accepts (the local minimum quality rises) is
// committed. Vertices never move; constrained faces are never removed; regions never mix.
#pragma once
#include <array>
#include <limits>

#include "core/mesh/tet_mesh.h"
#include "core/quality/quality.h"
#include "core/quality/time_step_guard.h"

namespace cvtmesh {

struct SwapOptions {
  // Larger-is-better measure deciding the swaps: kQ (default) or kMinAngle (the minimal dihedral
  // angle criterion), kRadiusRatio, kGmshIcn. kMaxAngle throws std::invalid_argument.
  Measure measure = Measure::kQ;
  int max_passes = 20;
  // A swap is accepted when new_min > old_min + min_gain * |old_min| (see accept_swap.h).
  double min_gain = 1e-6;
  // Only tets whose quality is below this are tried (+inf: all of them).
  double quality_threshold = std::numeric_limits<double>::infinity();
  int max_ring = 7;          // largest edge ring tried, 3..7
  bool flip23 = true;        // try 2-3 flips on the faces
  bool remove_edges = true;  // try edge removals (3-2 flips included) on the edges
  bool compact = true;       // remove the dead slots at the end (compact_tets)
  // Optional second measure that must not get worse: a swap is also refused when the minimum of
  // the new tets in `guard_measure` is below that of the old ones (e.g. dihedral-angle flips that
  // must not lower the minimum Q).
  bool use_guard = false;
  Measure guard_measure = Measure::kQ;
  // The guard only protects values below this floor: the new minimum must be at least
  // min(old minimum, guard_floor) (-inf: must not decrease at all).
  double guard_floor = -std::numeric_limits<double>::infinity();
  // The time-step guard (time_step_guard.h; off by default): a swap is also refused when the
  // new tets' smallest element time step is below min(the old tets', floor).
  TimeStepGuard dt_guard;
};

struct SwapStats {
  int passes = 0;
  long nb_flip23 = 0;
  long nb_flip32 = 0;                    // edge removals with a ring of 3
  long nb_edge_removals = 0;             // edge removals with a ring of 4..7
  std::array<long, 8> nb_by_ring{};      // edge removals by ring size n (index 3..7)
  long nb_tried = 0;                     // tets examined over all passes
  double min_before = 0, min_after = 0;  // global minimum quality in options.measure
  long nb_tets_before = 0, nb_tets_after = 0;
};

// Improves mesh in place. Never lowers the global minimum quality in options.measure (every
// committed swap raises the minimum of the tets it replaces), never creates an inverted tet.
// Builds mesh.adj if it is not built; leaves it valid. A pass is O(#T log #T) plus O(1) per
// operation tried. Throws std::invalid_argument for bad options.
SwapStats swap_slivers(TetMesh& mesh, const SwapOptions& options = {});

}  // namespace cvtmesh
