#include "core/mesh/vertex_star.h"

#include <algorithm>

namespace cvtmesh {

std::vector<int> vertex_neighbors(const TetMesh& m, const VertexStar& s, int v) {
  std::vector<int> n;
  for (const int* t = s.begin_of(v); t != s.end_of(v); ++t)
    for (int k = 0; k < 4; ++k) {
      const int w = m.tets[4 * *t + k];
      if (w != v) n.push_back(w);
    }
  std::sort(n.begin(), n.end());
  n.erase(std::unique(n.begin(), n.end()), n.end());
  return n;
}

}  // namespace cvtmesh
