// The 2-3 flip: the face shared by two tets (a,b,c | d) and (a,b,c | e) is replaced by the edge
// (d,e), and the two tets by the three tets (a,b,d,e), (b,c,d,e), (c,a,d,e) around it.
#pragma once
#include "core/mesh/tet_mesh.h"
#include "core/swap/accept_swap.h"
#include "core/swap/constrained_faces.h"
#include "core/swap/swap_plan.h"

namespace cvtmesh {

// Plans the 2-3 flip of face f (opposite local vertex f, 0..3) of the live tet t; changes
// nothing. status: kBoundary if no tet lies behind the face, kConstrainedFace if the face is in
// `constrained`, kMixedRegions if the two tets differ in region, kNotConvex if a new tet is not
// positively oriented (exact orient3d: the union of the two tets is not convex across the face).
// Needs mesh.adj. Throws std::invalid_argument for a dead tet or f outside 0..3.
SwapPlan plan_flip23(const TetMesh& mesh, const ConstrainedFaces& constrained, int t, int f);

// Plans the flip and commits it (apply_swap) when it is valid and, if `criterion` is given, the
// criterion accepts it (status kRejected otherwise). Builds the constrained-face set from
// mesh.tris (O(#F)): for repeated use, plan + accept_swap + apply_swap instead.
SwapPlan flip23(TetMesh& mesh, int t, int f, const SwapCriterion* criterion = nullptr);

}  // namespace cvtmesh
