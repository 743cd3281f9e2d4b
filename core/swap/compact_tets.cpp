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

}  // namespace cvtmesh
