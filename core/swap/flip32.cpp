#include <utility>

#include "core/swap/flip32.h"

#include "core/swap/apply_swap.h"
#include "core/swap/remove_edge.h"

namespace cvtmesh {

SwapPlan plan_flip32(const TetMesh& mesh, const ConstrainedFaces& constrained, int t, int e,
                     Measure measure) {
  SwapPlan plan = plan_remove_edge(mesh, constrained, t, e, measure, /*max_ring=*/3);
  if (plan.status == SwapStatus::kOk && plan.old_tets.size() != 3)
    plan.status = SwapStatus::kRingSize;
  return plan;
}

SwapPlan flip32(TetMesh& mesh, int t, int e, const SwapCriterion* criterion) {
  const Measure m = criterion ? criterion->measure : Measure::kQ;
  SwapPlan plan = plan_flip32(mesh, constrained_faces(mesh), t, e, m);
  return apply_if_accepted(mesh, std::move(plan), criterion);
}

}  // namespace cvtmesh
