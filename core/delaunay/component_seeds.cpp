#include "core/delaunay/component_seeds.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "core/geometry/predicates.h"
#include "core/mesh/face_key.h"

namespace cvtmesh {

std::vector<std::pair<int, std::array<double, 3>>> component_seeds(const TetMesh& m) {
  const int nt = m.nb_tets();
  std::unordered_set<FaceKey, FaceKeyHash> constrained;
  for (int f = 0; f < m.nb_tris(); ++f)
    constrained.insert(face_key(m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]));
  std::vector<int> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::unordered_map<FaceKey, int, FaceKeyHash> open;
  open.reserve(2 * static_cast<std::size_t>(nt));
  for (int t = 0; t < nt; ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    for (int f = 0; f < 4; ++f) {
      const FaceKey k = face_key(v[kTetFace[f][0]], v[kTetFace[f][1]], v[kTetFace[f][2]]);
      if (constrained.count(k)) continue;
      auto [it, fresh] = open.emplace(k, t);
      if (!fresh) {
        parent[find(t)] = find(it->second);
        open.erase(it);
      }
    }
  }
  std::unordered_map<int, std::pair<double, int>> best;  // component root -> (volume, tet)
  for (int t = 0; t < nt; ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    const double vol = orient3d(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
    auto [it, fresh] = best.emplace(find(t), std::make_pair(vol, t));
    if (!fresh && vol > it->second.first) it->second = {vol, t};
  }
  std::vector<std::pair<int, std::array<double, 3>>> seeds;
  std::vector<int> order;
  for (const auto& [root, b] : best) order.push_back(b.second);
  std::sort(order.begin(), order.end());  // deterministic
  for (int t : order) {
    const int* v = &m.tets[4 * t];
    std::array<double, 3> c{0, 0, 0};
    for (int k = 0; k < 4; ++k)
      for (int d = 0; d < 3; ++d) c[d] += 0.25 * m.point(v[k])[d];
    seeds.push_back({m.tet_region[t], c});
  }
  return seeds;
}

}  // namespace cvtmesh
