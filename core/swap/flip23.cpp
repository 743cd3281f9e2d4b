#include <utility>

#include "core/swap/flip23.h"

#include <stdexcept>
#include <string>

#include "core/geometry/predicates.h"
#include "core/swap/apply_swap.h"

namespace cvtmesh {

SwapPlan plan_flip23(const TetMesh& mesh, const ConstrainedFaces& constrained, int t, int f) {
  if (t < 0 || t >= mesh.nb_tets() || mesh.tets[4 * static_cast<std::size_t>(t)] < 0)
    throw std::invalid_argument("flip23: tet " + std::to_string(t) + " is not a live tet");
  if (f < 0 || f > 3) throw std::invalid_argument("flip23: face index must be 0..3");
  SwapPlan plan;
  const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
  const int behind = mesh.adj[4 * static_cast<std::size_t>(t) + f];
  if (behind < 0) {
    plan.status = SwapStatus::kBoundary;
    return plan;
  }
  const int t1 = behind / 4;
  // (a,b,c) is oriented outwards from t: d = t's apex is below it, e = t1's apex above it.
  const int a = tv[kTetFace[f][0]], b = tv[kTetFace[f][1]], c = tv[kTetFace[f][2]];
  const int d = tv[f], e = mesh.tets[static_cast<std::size_t>(behind)];
  plan.old_tets = {t, t1};
  plan.region = mesh.tet_region[t];
  if (constrained.count(face_key(a, b, c))) {
    plan.status = SwapStatus::kConstrainedFace;
    return plan;
  }
  if (mesh.tet_region[t1] != plan.region) {
    plan.status = SwapStatus::kMixedRegions;
    return plan;
  }
  plan.new_tets = {{a, b, d, e}, {b, c, d, e}, {c, a, d, e}};
  for (const auto& nt : plan.new_tets)
    if (orient3d(mesh.point(nt[0]), mesh.point(nt[1]), mesh.point(nt[2]), mesh.point(nt[3])) <= 0) {
      plan.status = SwapStatus::kNotConvex;
      return plan;
    }
  return plan;
}

SwapPlan flip23(TetMesh& mesh, int t, int f, const SwapCriterion* criterion) {
  SwapPlan plan = plan_flip23(mesh, constrained_faces(mesh), t, f);
  return apply_if_accepted(mesh, std::move(plan), criterion);
}

}  // namespace cvtmesh
