#include "core/swap/apply_swap.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/mesh/face_key.h"
#include "core/util/error.h"

namespace cvtmesh {

void apply_swap(TetMesh& mesh, SwapPlan& plan, std::vector<int>* free_slots) {
  if (plan.status != SwapStatus::kOk)
    throw std::invalid_argument(std::string("apply_swap: the plan is not valid (") +
                                swap_status_name(plan.status) + ")");
  const auto& old_tets = plan.old_tets;
  const int nb_old = static_cast<int>(old_tets.size());
  const int nb_new = static_cast<int>(plan.new_tets.size());
  auto is_old = [&](int t) {
    return std::find(old_tets.begin(), old_tets.end(), t) != old_tets.end();
  };

  // The cavity's boundary faces and what lies behind each (a slot 4t'+f', or -1).
  std::vector<FaceKey> outer_key;
  std::vector<int> outer_behind;
  for (int t : old_tets) {
    const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
    if (tv[0] < 0) throw std::invalid_argument("apply_swap: tet " + std::to_string(t) + " is dead");
    for (int f = 0; f < 4; ++f) {
      const int behind = mesh.adj[4 * static_cast<std::size_t>(t) + f];
      if (behind >= 0 && is_old(behind / 4)) continue;
      outer_key.push_back(face_key(tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]]));
      outer_behind.push_back(behind);
    }
  }

  // Match every face of every new tet, before changing anything: either another new tet's face
  // (inner = 4j+g) or a boundary face of the cavity (outer index).
  std::vector<FaceKey> keys(4 * static_cast<std::size_t>(nb_new));
  for (int i = 0; i < nb_new; ++i) {
    const auto& nt = plan.new_tets[i];
    for (int f = 0; f < 4; ++f)
      keys[4 * i + f] = face_key(nt[kTetFace[f][0]], nt[kTetFace[f][1]], nt[kTetFace[f][2]]);
  }
  std::vector<int> inner(4 * static_cast<std::size_t>(nb_new), -1), outer(inner.size(), -1);
  std::vector<char> outer_used(outer_key.size(), 0);
  for (int a = 0; a < 4 * nb_new; ++a) {
    for (int b = 0; b < 4 * nb_new && inner[a] < 0; ++b)
      if (b / 4 != a / 4 && keys[b] == keys[a]) inner[a] = b;
    if (inner[a] >= 0) continue;
    for (std::size_t o = 0; o < outer_key.size(); ++o)
      if (!outer_used[o] && outer_key[o] == keys[a]) {
        outer_used[o] = 1;
        outer[a] = static_cast<int>(o);
        break;
      }
    if (outer[a] < 0)
      throw InvariantError(
          "apply_swap: a face of a new tet is neither shared by another new tet "
          "nor a boundary face of the cavity");
  }
  if (std::find(outer_used.begin(), outer_used.end(), 0) != outer_used.end())
    throw InvariantError(
        "apply_swap: a boundary face of the cavity is not covered by the new tets");

  // Slots for the new tets: the old ones, then free ones, then appended.
  plan.new_ids.clear();
  for (int i = 0; i < nb_new; ++i) {
    int slot = -1;
    if (i < nb_old) {
      slot = old_tets[i];
    } else {
      while (free_slots && !free_slots->empty() && slot < 0) {
        const int s = free_slots->back();
        free_slots->pop_back();
        if (s < mesh.nb_tets() && mesh.tets[4 * static_cast<std::size_t>(s)] < 0) slot = s;
      }
      if (slot < 0) {
        slot = mesh.nb_tets();
        mesh.tets.insert(mesh.tets.end(), {-1, -1, -1, -1});
        mesh.adj.insert(mesh.adj.end(), {-1, -1, -1, -1});
        mesh.tet_region.push_back(plan.region);
        if (!mesh.tet_tags.empty()) mesh.tet_tags.push_back(0);
      }
    }
    plan.new_ids.push_back(slot);
  }
  for (int i = nb_new; i < nb_old; ++i) {
    const std::size_t s = 4 * static_cast<std::size_t>(old_tets[i]);
    std::fill(mesh.tets.begin() + s, mesh.tets.begin() + s + 4, -1);
    std::fill(mesh.adj.begin() + s, mesh.adj.begin() + s + 4, -1);
    if (free_slots) free_slots->push_back(old_tets[i]);
  }

  for (int i = 0; i < nb_new; ++i) {
    const int slot = plan.new_ids[i];
    std::copy(plan.new_tets[i].begin(), plan.new_tets[i].end(),
              mesh.tets.begin() + 4 * static_cast<std::size_t>(slot));
    mesh.tet_region[slot] = plan.region;
    if (!mesh.tet_tags.empty()) mesh.tet_tags[slot] = 0;
  }
  for (int a = 0; a < 4 * nb_new; ++a) {
    const int here = 4 * plan.new_ids[a / 4] + a % 4;
    if (inner[a] >= 0) {
      mesh.adj[here] = 4 * plan.new_ids[inner[a] / 4] + inner[a] % 4;
    } else {
      const int behind = outer_behind[outer[a]];
      mesh.adj[here] = behind;
      if (behind >= 0) mesh.adj[behind] = here;
    }
  }
}

SwapPlan apply_if_accepted(TetMesh& mesh, SwapPlan plan, const SwapCriterion* criterion) {
  if (plan.status != SwapStatus::kOk) return plan;
  if (criterion && !accept_swap(mesh, plan, *criterion)) {
    plan.status = SwapStatus::kRejected;
    return plan;
  }
  apply_swap(mesh, plan);
  return plan;
}

}  // namespace cvtmesh
