#include "core/swap/compact_tets.h"

#include <vector>

#include "core/mesh/build_adjacency.h"

namespace cvtmesh {

int compact_tets(TetMesh& mesh) {
  const int nt = mesh.nb_tets();
  const bool has_adj = mesh.adj.size() == mesh.tets.size();
  const bool has_tags = mesh.tet_tags.size() == static_cast<std::size_t>(nt);
  std::vector<int> new_id(static_cast<std::size_t>(nt), -1);
  int live = 0;
  for (int t = 0; t < nt; ++t)
    if (mesh.tets[4 * static_cast<std::size_t>(t)] >= 0) new_id[t] = live++;
  if (live == nt) {
    if (!has_adj) build_adjacency(mesh);
    return 0;
  }
  for (int t = 0; t < nt; ++t) {
    const int n = new_id[t];
    if (n < 0) continue;
    for (int k = 0; k < 4; ++k) {
      mesh.tets[4 * static_cast<std::size_t>(n) + k] =
          mesh.tets[4 * static_cast<std::size_t>(t) + k];
      if (has_adj) {
        const int o = mesh.adj[4 * static_cast<std::size_t>(t) + k];
        mesh.adj[4 * static_cast<std::size_t>(n) + k] =
            (o < 0 || new_id[o / 4] < 0) ? -1 : 4 * new_id[o / 4] + o % 4;
      }
    }
    mesh.tet_region[n] = mesh.tet_region[t];
    if (has_tags) mesh.tet_tags[n] = mesh.tet_tags[t];
  }
  mesh.tets.resize(4 * static_cast<std::size_t>(live));
  mesh.tet_region.resize(static_cast<std::size_t>(live));
  if (has_tags) mesh.tet_tags.resize(static_cast<std::size_t>(live));
  if (has_adj)
    mesh.adj.resize(4 * static_cast<std::size_t>(live));
  else
    build_adjacency(mesh);
  return nt - live;
}

int compact_tets_fill(TetMesh& mesh) {
  if (mesh.adj.size() != mesh.tets.size()) return compact_tets(mesh);
  const bool has_tags = mesh.tet_tags.size() == mesh.tet_region.size();
  int end = mesh.nb_tets();
  const int before = end;
  auto dead = [&](int t) { return mesh.tets[4 * static_cast<std::size_t>(t)] < 0; };
  for (int hole = 0; hole < end; ++hole) {
    if (!dead(hole)) continue;
    while (end > hole + 1 && dead(end - 1)) --end;
    if (end == hole + 1) {  // nothing live after the hole
      end = hole;
      break;
    }
    const int from = --end;  // live: move it into the hole
    for (int k = 0; k < 4; ++k) {
      const std::size_t i = 4 * static_cast<std::size_t>(hole) + k,
                        j = 4 * static_cast<std::size_t>(from) + k;
      mesh.tets[i] = mesh.tets[j];
      const int o = mesh.adj[j];
      mesh.adj[i] = o;
      if (o >= 0) mesh.adj[o] = 4 * hole + k;
      mesh.tets[j] = -1;
    }
    mesh.tet_region[hole] = mesh.tet_region[from];
    if (has_tags) mesh.tet_tags[hole] = mesh.tet_tags[from];
  }
  while (end > 0 && dead(end - 1)) --end;
  mesh.tets.resize(4 * static_cast<std::size_t>(end));
  mesh.adj.resize(4 * static_cast<std::size_t>(end));
  mesh.tet_region.resize(end);
  if (has_tags) mesh.tet_tags.resize(end);
  return before - end;
}

}  // namespace cvtmesh
