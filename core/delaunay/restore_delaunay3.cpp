#include "core/delaunay/restore_delaunay3.h"

#include <algorithm>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/vertex_tets.h"
#include "core/swap/apply_swap.h"
#include "core/swap/compact_tets.h"
#include "core/swap/flip23.h"
#include "core/swap/flip32.h"

namespace cvtmesh {
namespace {

// Face f of live tet t is unconstrained and the vertex behind it is strictly inside t's
// circumsphere.
bool non_delaunay(const TetMesh& m, const ConstrainedFaces& cf, int t, int f) {
  const int o = m.adj[4 * t + f];
  if (o < 0) return false;
  const int* tv = &m.tets[4 * t];
  const int e = m.tets[4 * (o / 4) + o % 4];
  if (insphere(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3]), m.point(e)) <= 0)
    return false;
  return !cf.count(face_key(tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]]));
}

}  // namespace

namespace {

// Lawson flips from the faces in `stack` until no unconstrained face reachable from them is
// non-Delaunay or none can be flipped.
void flip_until_delaunay(TetMesh& m, const ConstrainedFaces& cf,
                         std::vector<std::pair<int, int>>& stack, RestoreDelaunayStats& st) {
  const int nt = m.nb_tets();
  std::vector<int> free_slots;
  std::vector<std::pair<int, int>> stuck;
  auto push_tets = [&](const std::vector<int>& ids) {
    for (int id : ids)
      for (int f = 0; f < 4; ++f) stack.push_back({id, f});
  };
  // Each flip lowers the lifted triangulation strictly, so the loop ends; the cap guards against
  // a bug, not against the algorithm. Faces no flip could remove are retried after the others
  // (a flip elsewhere can make their reflex edge removable), while that makes progress.
  long budget = 50L * nt + 1000;
  for (int round = 0; round < 8; ++round) {
    const int flips_before = st.nb_flips23 + st.nb_flips32;
    while (!stack.empty() && budget-- > 0) {
      const auto [t, f] = stack.back();
      stack.pop_back();
      if (m.tets[4 * t] < 0 || !non_delaunay(m, cf, t, f)) continue;
      SwapPlan plan = plan_flip23(m, cf, t, f);
      if (plan.status == SwapStatus::kOk) {
        apply_swap(m, plan, &free_slots);
        ++st.nb_flips23;
        push_tets(plan.new_ids);
        continue;
      }
      if (plan.status != SwapStatus::kNotConvex) {
        stuck.push_back({t, f});
        continue;
      }
      // The union of the two tets is not convex across the face: remove the reflex edge of the
      // face if exactly three tets surround it (3-2 flip).
      bool done = false;
      for (int e = 0; e < 6 && !done; ++e) {
        // The edges of face f are those not incident to local vertex f.
        if (kTetEdge[e][0] == f || kTetEdge[e][1] == f) continue;
        SwapPlan p32 = plan_flip32(m, cf, t, e);
        if (p32.status != SwapStatus::kOk) continue;
        apply_swap(m, p32, &free_slots);
        ++st.nb_flips32;
        push_tets(p32.new_ids);
        done = true;
      }
      if (!done) stuck.push_back({t, f});
    }
    if (stuck.empty() || st.nb_flips23 + st.nb_flips32 == flips_before || budget <= 0) break;
    stack.swap(stuck);
    stuck.clear();
  }
  // Every face that may be non-Delaunay is in the stack or in `stuck` (a flip pushes the faces of
  // the tets it makes; the symmetric insphere test makes a face's two sides one): listed when it
  // still is. (The stack is empty unless the budget ran out or the last round ended.)
  for (const auto* list : {&stuck, &stack})
    for (const auto& [t, f] : *list)
      if (m.tets[4 * t] >= 0 && non_delaunay(m, cf, t, f)) {
        const int* tv = &m.tets[4 * t];
        st.stuck_faces.push_back(
            face_key(tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]]));
      }
  std::sort(st.stuck_faces.begin(), st.stuck_faces.end());
  st.stuck_faces.erase(std::unique(st.stuck_faces.begin(), st.stuck_faces.end()),
                       st.stuck_faces.end());
  st.nb_stuck = static_cast<int>(st.stuck_faces.size());
  if (!free_slots.empty()) compact_tets_fill(m);  // tet order is restored by the Lloyd loop
  st.ok = st.nb_stuck == 0;
}

}  // namespace

RestoreDelaunayStats restore_delaunay_by_flips(TetMesh& m, const ConstrainedFaces& cf,
                                               bool check_orientation) {
  RestoreDelaunayStats st;
  const int nt = m.nb_tets();
  if (check_orientation && last_non_positive_tet(m) >= 0) {
    st.inverted = true;
    return st;
  }
  // Work stack of (tet, face); entries are re-checked when popped (slots get reused).
  std::vector<std::pair<int, int>> stack;
  std::vector<unsigned char> bad(nt, 0);  // bit f: face f is to be flipped (tested in parallel)
#pragma omp parallel for schedule(static, 1024) if (nt > 1024)
  for (int t = 0; t < nt; ++t)
    if (m.tets[4 * t] >= 0)
      for (int f = 0; f < 4; ++f)
        if (m.adj[4 * t + f] > 4 * t + f && non_delaunay(m, cf, t, f)) bad[t] |= 1u << f;
  for (int t = 0; t < nt; ++t)
    for (int f = 0; f < 4; ++f)
      if (bad[t] >> f & 1) stack.push_back({t, f});
  flip_until_delaunay(m, cf, stack, st);
  return st;
}

RestoreDelaunayStats restore_delaunay_in(TetMesh& m, const ConstrainedFaces& cf,
                                         const std::vector<int>& tets) {
  RestoreDelaunayStats st;
  std::vector<std::pair<int, int>> stack;
  for (int t : tets) {
    if (m.tets[4 * t] < 0) continue;
    for (int f = 0; f < 4; ++f)
      if (non_delaunay(m, cf, t, f)) stack.push_back({t, f});
  }
  flip_until_delaunay(m, cf, stack, st);
  return st;
}

}  // namespace cvtmesh
