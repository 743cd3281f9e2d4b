// Edge removal: the n = 3..7 tets around an interior edge (p,q) with ring r_0..r_{n-1} are
// replaced by 2n-4 tets: for each triangle (r_a,r_b,r_c) of a triangulation of the ring polygon,
// the tets (r_a,r_b,r_c,q) and (r_a,r_c,r_b,p). The triangulation is the one of the precomputed
// table (polygon_triangulations.h) whose new tets have the largest minimum quality (max-min).
// n = 3 is the 3-2 flip (flip32.h).
#pragma once

#include <limits>
#include "core/mesh/tet_mesh.h"
#include "core/quality/quality.h"
#include "core/swap/accept_swap.h"
#include "core/swap/constrained_faces.h"
#include "core/swap/edge_ring.h"
#include "core/swap/swap_plan.h"

namespace cvtmesh {

// Plans the removal of edge e (local index into kTetEdge, 0..5) of the live tet t; changes
// nothing. Picks the max-min triangulation in `measure` among those whose 2n-4 tets are all
// positively oriented (exact orient3d), and fills plan.old_min/new_min (quality_known).
// status: kBoundary (open ring: the edge is on the boundary), kRingSize (more than max_ring
// tets, max_ring <= 7), kMixedRegions, kConstrainedFace (a face around the edge is in
// `constrained`), kNotConvex (no valid triangulation). Needs mesh.adj.
// Throws std::invalid_argument for a dead tet, e outside 0..5 or max_ring outside 3..7.
SwapPlan plan_remove_edge(const TetMesh& mesh, const ConstrainedFaces& constrained, int t, int e,
                          Measure measure = Measure::kQ, int max_ring = 7);

// The same from a ring already walked (edge_ring.h): status kBoundary or kRingSize unless
// ring.closed. With a `floor` (a caller that accepts no plan whose new minimum is at or below
// it, e.g. the ring's old minimum): only the triangulations whose minimum is above it are
// searched, status kRejected when there is none; the same plan otherwise (the max-min
// triangulation, exactly), for fewer quality evaluations.
SwapPlan plan_remove_edge(const TetMesh& mesh, const ConstrainedFaces& constrained,
                          const EdgeRing& ring, Measure measure = Measure::kQ,
                          double floor = -std::numeric_limits<double>::infinity());

// Plans the removal (choosing the triangulation in the criterion's measure, kQ without one) and
// commits it when valid and accepted by `criterion` if given (status kRejected otherwise).
// Builds the constrained-face set from mesh.tris (O(#F)).
SwapPlan remove_edge(TetMesh& mesh, int t, int e, const SwapCriterion* criterion = nullptr);

}  // namespace cvtmesh
