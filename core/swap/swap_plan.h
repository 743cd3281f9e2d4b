// SwapPlan: a local retriangulation proposed by a topological operation (2-3 flip, 3-2 flip,
// edge removal), before anything is changed. Planning checks validity only (exact orientation,
// constrained faces, regions); whether to commit is decided separately (accept_swap.h) and
// committing is apply_swap.h. Operations never move a vertex; only a vertex insertion
// (insert_vertex.h) adds one.
#pragma once
#include <array>
#include <vector>

#include "core/quality/quality.h"

namespace cvtmesh {

enum class SwapStatus {
  kOk,               // a valid plan / a committed operation
  kRejected,         // valid, but the acceptance criterion refused it
  kConstrainedFace,  // it would remove a constrained (boundary or interface) triangle
  kBoundary,         // the face has no tet behind it, or the edge is on the boundary (open ring)
  kMixedRegions,     // the tets involved belong to different regions
  kNotConvex,        // a new tet would be inverted or flat (exact orient3d)
  kRingSize,         // the number of tets around the edge is not what the operation handles
  kInteriorVertex,   // a vertex insertion's cavity has a vertex inside (it would be lost)
};

const char* swap_status_name(SwapStatus s);

struct SwapPlan {
  SwapStatus status = SwapStatus::kOk;
  // The tets removed (live tet ids, 0-based).
  std::vector<int> old_tets;
  // The tets that replace them: vertex quadruples, each positively oriented (orient3d > 0).
  // Their union is exactly the union of old_tets (same boundary faces).
  std::vector<std::array<int, 4>> new_tets;
  // Region tag shared by all old tets (and given to the new ones).
  int region = 0;
  // Minimum quality of old_tets / new_tets in `measure`, when the planner computed them
  // (plan_remove_edge does, to pick the best triangulation); accept_swap computes them otherwise.
  bool quality_known = false;
  Measure measure = Measure::kQ;
  double old_min = 0, new_min = 0;
  // After apply_swap: the tet ids of the new tets, in new_tets order.
  std::vector<int> new_ids;
};

}  // namespace cvtmesh
