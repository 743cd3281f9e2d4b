// The 3-2 flip: the three tets around an interior edge (p,q) with ring (r0,r1,r2) are replaced
// by the two tets (r0,r1,r2,q) and (r0,r2,r1,p). The inverse of the 2-3 flip; edge removal with
// n = 3 (remove_edge.h).
#pragma once
#include "core/mesh/tet_mesh.h"
#include "core/swap/accept_swap.h"
#include "core/swap/constrained_faces.h"
#include "core/swap/swap_plan.h"

namespace cvtmesh {

// Plans the 3-2 flip of edge e (local index into kTetEdge, 0..5) of the live tet t; changes
// nothing. status kRingSize unless exactly three tets surround the edge; otherwise as
// plan_remove_edge. The plan carries old_min/new_min in `measure`.
SwapPlan plan_flip32(const TetMesh& mesh, const ConstrainedFaces& constrained, int t, int e,
                     Measure measure = Measure::kQ);

// Plans and commits when valid and accepted by `criterion` if given (kRejected otherwise).
// Builds the constrained-face set from mesh.tris (O(#F)).
SwapPlan flip32(TetMesh& mesh, int t, int e, const SwapCriterion* criterion = nullptr);

}  // namespace cvtmesh
