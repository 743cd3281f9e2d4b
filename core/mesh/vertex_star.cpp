#include "core/mesh/vertex_star.h"

#include <algorithm>

namespace cvtmesh {

VertexStar build_vertex_star(const TetMesh& m) {
  VertexStar s;
  const int nv = m.nb_vertices(), nt = m.nb_tets();
  s.offset.assign(nv + 1, 0);
  for (int t = 0; t < nt; ++t)
    if (m.tets[4 * t] >= 0)
      for (int k = 0; k < 4; ++k) ++s.offset[m.tets[4 * t + k] + 1];
  for (int v = 0; v < nv; ++v) s.offset[v + 1] += s.offset[v];
  s.tet.resize(s.offset[nv]);
  std::vector<int> fill(s.offset.begin(), s.offset.end() - 1);
  for (int t = 0; t < nt; ++t)
    if (m.tets[4 * t] >= 0)
      for (int k = 0; k < 4; ++k) s.tet[fill[m.tets[4 * t + k]]++] = t;
  return s;
}

std::vector<int> vertex_neighbors(const TetMesh& m, const VertexStar& s, int v) {
  std::vector<int> n;
  for (int i = s.offset[v]; i < s.offset[v + 1]; ++i)
    for (int k = 0; k < 4; ++k) {
      const int w = m.tets[4 * s.tet[i] + k];
      if (w != v) n.push_back(w);
    }
  std::sort(n.begin(), n.end());
  n.erase(std::unique(n.begin(), n.end()), n.end());
  return n;
}

}  // namespace cvtmesh
