#include "core/swap/plan_adds_existing_simplex.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "core/mesh/walk_vertex_star.h"

namespace cvtmesh {
namespace {

using Simplex = std::array<int, 3>;  // sorted; an edge has [2] = -1

Simplex edge_of(int a, int b) {
  return a < b ? Simplex{a, b, -1} : Simplex{b, a, -1};
}

Simplex face_of(int a, int b, int c) {
  Simplex s{a, b, c};
  std::sort(s.begin(), s.end());
  return s;
}

// Every edge and triangle of the tet v.
void simplices_of(const int* v, std::vector<Simplex>& out) {
  for (const auto& e : kTetEdge) out.push_back(edge_of(v[e[0]], v[e[1]]));
  for (const auto& f : kTetFace) out.push_back(face_of(v[f[0]], v[f[1]], v[f[2]]));
}

bool holds(const int* tv, const Simplex& s) {
  for (int k = 0; k < 3; ++k)
    if (s[k] >= 0 && std::find(tv, tv + 4, s[k]) == tv + 4) return false;
  return true;
}

}  // namespace

bool plan_adds_existing_simplex(const TetMesh& mesh, const SwapPlan& plan) {
  std::vector<Simplex> old_simplices, fresh;
  for (int t : plan.old_tets)
    simplices_of(&mesh.tets[4 * static_cast<std::size_t>(t)], old_simplices);
  std::sort(old_simplices.begin(), old_simplices.end());
  for (const auto& nt : plan.new_tets) simplices_of(nt.data(), fresh);
  std::sort(fresh.begin(), fresh.end());
  fresh.erase(std::unique(fresh.begin(), fresh.end()), fresh.end());
  std::vector<std::pair<int, std::vector<int>>> stars;  // vertex -> its star, walked once
  for (const Simplex& s : fresh) {
    if (std::binary_search(old_simplices.begin(), old_simplices.end(), s)) continue;
    const int a = s[0];
    auto it = std::find_if(stars.begin(), stars.end(), [a](const auto& p) { return p.first == a; });
    if (it == stars.end()) {
      int from = -1;
      for (int t : plan.old_tets) {
        const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
        if (std::find(tv, tv + 4, a) != tv + 4) from = t;
      }
      if (from < 0) continue;  // not a swap's plan: nothing to walk from
      stars.emplace_back(a, walk_vertex_star(mesh, from, a));
      it = stars.end() - 1;
    }
    for (int t : it->second) {
      if (std::find(plan.old_tets.begin(), plan.old_tets.end(), t) != plan.old_tets.end()) continue;
      if (holds(&mesh.tets[4 * static_cast<std::size_t>(t)], s)) return true;
    }
  }
  return false;
}

}  // namespace cvtmesh
