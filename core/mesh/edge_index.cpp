#include "core/mesh/edge_index.h"

namespace cvtmesh {

EdgeIndex::EdgeIndex(const std::vector<int>& edges, int nb_vertices) {
  const int ne = static_cast<int>(edges.size() / 2);
  start_.assign(static_cast<std::size_t>(nb_vertices) + 1, 0);
  for (int v : edges) ++start_[v + 1];
  for (int v = 0; v < nb_vertices; ++v) start_[v + 1] += start_[v];
  other_.resize(start_[nb_vertices]);
  edge_.resize(start_[nb_vertices]);
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (int e = 0; e < ne; ++e)
    for (int k = 0; k < 2; ++k) {
      const int u = edges[2 * e + k], w = edges[2 * e + 1 - k];
      other_[fill[u]] = w;
      edge_[fill[u]++] = e;
    }
}

}  // namespace cvtmesh
