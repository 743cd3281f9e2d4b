#include "core/swap/apply_swap.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/mesh/face_key.h"
#include "core/util/error.h"

namespace cvtmesh {

namespace {

// The boundary faces of a cavity (live tets) and what lies behind each (a slot 4t'+f', or -1).
struct CavityFaces {
  std::vector<FaceKey> key;
  std::vector<int> behind;
};

// Fills `c` (cleared first: its arrays are reused).
void cavity_faces(const TetMesh& mesh, const std::vector<int>& old_tets, const char* caller,
                  CavityFaces& c) {
  auto is_old = [&](int t) {
    return std::find(old_tets.begin(), old_tets.end(), t) != old_tets.end();
  };
  c.key.clear();
  c.behind.clear();
  for (int t : old_tets) {
    const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
    if (tv[0] < 0)
      throw std::invalid_argument(std::string(caller) + ": tet " + std::to_string(t) + " is dead");
    for (int f = 0; f < 4; ++f) {
      const int behind = mesh.adj[4 * static_cast<std::size_t>(t) + f];
      if (behind >= 0 && is_old(behind / 4)) continue;
      c.key.push_back(face_key(tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]]));
      c.behind.push_back(behind);
    }
  }
}

// Every face a = 4i+f of the new tets matched, before anything changes: to another new tet's
// face (inner[a] = 4j+g), else to a boundary face of the cavity (outer[a] = its index), else
// neither (both -1).
struct FaceMatch {
  std::vector<int> inner, outer;
  std::vector<char> outer_used;
  std::vector<FaceKey> keys;  // the new tets' faces (scratch)
};

bool same_key(const FaceKey& a, const FaceKey& b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// Fills `m` (its arrays are reused).
void match_new_faces(const CavityFaces& cavity, const std::vector<std::array<int, 4>>& new_tets,
                     FaceMatch& m) {
  const int nb_new = static_cast<int>(new_tets.size());
  std::vector<FaceKey>& keys = m.keys;
  keys.resize(4 * static_cast<std::size_t>(nb_new));
  for (int i = 0; i < nb_new; ++i) {
    const auto& nt = new_tets[i];
    for (int f = 0; f < 4; ++f)
      keys[4 * i + f] = face_key(nt[kTetFace[f][0]], nt[kTetFace[f][1]], nt[kTetFace[f][2]]);
  }
  m.inner.assign(keys.size(), -1);
  m.outer.assign(keys.size(), -1);
  m.outer_used.assign(cavity.key.size(), 0);
  for (int a = 0; a < 4 * nb_new; ++a) {
    for (int b = 0; b < 4 * nb_new && m.inner[a] < 0; ++b)
      if (b / 4 != a / 4 && same_key(keys[b], keys[a])) m.inner[a] = b;
    if (m.inner[a] >= 0) continue;
    for (std::size_t o = 0; o < cavity.key.size(); ++o)
      if (!m.outer_used[o] && same_key(cavity.key[o], keys[a])) {
        m.outer_used[o] = 1;
        m.outer[a] = static_cast<int>(o);
        break;
      }
  }
}

// The adjacency of the new tets (in `slots`) and of the tets behind the cavity: a face matched
// to nothing has nothing behind it (-1).
void link_new_tets(TetMesh& mesh, const std::vector<int>& slots, const CavityFaces& cavity,
                   const FaceMatch& m) {
  for (std::size_t a = 0; a < m.inner.size(); ++a) {
    const int here = 4 * slots[a / 4] + static_cast<int>(a % 4);
    if (m.inner[a] >= 0) {
      mesh.adj[here] = 4 * slots[m.inner[a] / 4] + m.inner[a] % 4;
    } else if (m.outer[a] >= 0) {
      const int behind = cavity.behind[m.outer[a]];
      mesh.adj[here] = behind;
      if (behind >= 0) mesh.adj[behind] = here;
    } else {
      mesh.adj[here] = -1;
    }
  }
}

}  // namespace

void apply_swap(TetMesh& mesh, SwapPlan& plan, std::vector<int>* free_slots) {
  if (plan.status != SwapStatus::kOk)
    throw std::invalid_argument(std::string("apply_swap: the plan is not valid (") +
                                swap_status_name(plan.status) + ")");
  const auto& old_tets = plan.old_tets;
  const int nb_old = static_cast<int>(old_tets.size());
  const int nb_new = static_cast<int>(plan.new_tets.size());
  // Per-thread arrays reused from one swap to the next (the Lloyd iteration's serial Delaunay
  // flips apply ~10^4-10^5 swaps: 5 allocations each otherwise).
  thread_local CavityFaces cavity;
  thread_local FaceMatch match;
  cavity_faces(mesh, old_tets, "apply_swap", cavity);
  match_new_faces(cavity, plan.new_tets, match);
  for (std::size_t a = 0; a < match.inner.size(); ++a)
    if (match.inner[a] < 0 && match.outer[a] < 0)
      throw InvariantError(
          "apply_swap: a face of a new tet is neither shared by another new tet "
          "nor a boundary face of the cavity");
  if (std::find(match.outer_used.begin(), match.outer_used.end(), 0) != match.outer_used.end())
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
  link_new_tets(mesh, plan.new_ids, cavity, match);
}

std::vector<int> apply_boundary_retriangulation(TetMesh& mesh, const std::vector<int>& old_tets,
                                                const std::vector<std::array<int, 4>>& new_tets,
                                                int region) {
  if (mesh.adj.size() != mesh.tets.size())
    throw std::invalid_argument("apply_boundary_retriangulation: adjacency not built");
  CavityFaces cavity;
  FaceMatch match;
  cavity_faces(mesh, old_tets, "apply_boundary_retriangulation", cavity);
  match_new_faces(cavity, new_tets, match);
  for (std::size_t o = 0; o < cavity.key.size(); ++o)
    if (!match.outer_used[o] && cavity.behind[o] >= 0)
      throw InvariantError(
          "apply_boundary_retriangulation: a face of the cavity with a tet behind it is not "
          "covered by the new tets");
  for (int t : old_tets) {
    const std::size_t s = 4 * static_cast<std::size_t>(t);
    std::fill(mesh.tets.begin() + s, mesh.tets.begin() + s + 4, -1);
    std::fill(mesh.adj.begin() + s, mesh.adj.begin() + s + 4, -1);
  }
  std::vector<int> slots;
  for (const auto& t : new_tets) {
    slots.push_back(mesh.nb_tets());
    mesh.tets.insert(mesh.tets.end(), t.begin(), t.end());
    mesh.adj.insert(mesh.adj.end(), {-1, -1, -1, -1});
    mesh.tet_region.push_back(region);
    if (!mesh.tet_tags.empty()) mesh.tet_tags.push_back(0);
  }
  link_new_tets(mesh, slots, cavity, match);
  return slots;
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
