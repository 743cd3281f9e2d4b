// Commits a planned swap: replaces plan.old_tets by plan.new_tets and repairs the adjacency
// locally (O(size of the cavity), no O(#T) work). The move only; the decision is accept_swap.
#pragma once
#include <array>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/swap/accept_swap.h"
#include "core/swap/swap_plan.h"

namespace cvtmesh {

// New tets reuse the slots of the old ones first, then dead slots popped from *free_slots (if
// given), then are appended. Old slots left over are marked dead (all four ids -1, adjacency -1)
// and pushed onto *free_slots. Fills plan.new_ids. Keeps tet_region (plan.region) and tet_tags
// (0 for a new tet, when tet_tags is not empty) in step.
// Throws std::invalid_argument if plan.status is not kOk, InvariantError if the new tets do not
// have exactly the old cavity's boundary faces (a planner bug).
void apply_swap(TetMesh& mesh, SwapPlan& plan, std::vector<int>* free_slots = nullptr);

// A retriangulation at the boundary (a surface edge flip, flip_boundary_edges): the tets
// `old_tets` (live, one region) are marked dead (all four ids and adjacency -1) and `new_tets`
// appended (region `region`, tag 0); the adjacency is repaired locally, a face of a new tet that
// matches neither another new tet's nor one of the cavity's boundary faces becoming a boundary
// face (-1). Returns the new tets' slots. Throws std::invalid_argument if the adjacency is not
// built or an old tet is dead, InvariantError if a face of the cavity with a tet behind it is not
// covered by the new tets (the mesh would come apart there).
std::vector<int> apply_boundary_retriangulation(TetMesh& mesh, const std::vector<int>& old_tets,
                                                const std::vector<std::array<int, 4>>& new_tets,
                                                int region);

// The common tail of flip23 / flip32 / remove_edge: a valid plan is committed if there is no
// criterion or the criterion accepts it; otherwise its status becomes kRejected. Returns the plan.
SwapPlan apply_if_accepted(TetMesh& mesh, SwapPlan plan, const SwapCriterion* criterion);

}  // namespace cvtmesh
