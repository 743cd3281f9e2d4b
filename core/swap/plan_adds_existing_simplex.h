// A topological check next to the exact orientation tests of the swap planners: a plan whose new
// tets hold an edge or a triangle that its old tets do not hold, but that some other tet of the
// mesh already holds. In a mesh whose tets do not overlap this cannot happen (the new edge would
// cross the cavity); where a moved boundary folds over itself before it is repaired (igl_bunny's
// ears, issue 17 stop 29), every new tet can be positive and the plan would still make a face
// of three tets: apply_swap then fails, or the mesh is left non-manifold.
#pragma once

#include "core/mesh/tet_mesh.h"
#include "core/swap/swap_plan.h"

namespace cvtmesh {

// True if a new edge or triangle of `plan` (one the old tets do not hold) is held by a live tet
// outside plan.old_tets. Walks the stars of the new simplices' first vertices from the old tets
// (walk_vertex_star): O(size of those stars). Needs mesh.adj; every vertex of plan.new_tets must
// be a vertex of plan.old_tets (the swaps' plans: edge removals, 2-3 and 3-2 flips).
bool plan_adds_existing_simplex(const TetMesh& mesh, const SwapPlan& plan);

}  // namespace cvtmesh
