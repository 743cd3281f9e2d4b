#include "core/mesh/constrain_kept_quad_edges.h"

#include <unordered_set>

#include "core/mesh/face_key.h"
#include "core/mesh/kept_quads.h"

namespace cvtmesh {

int constrain_kept_quad_edges(TriMesh2& m) {
  const KeptQuads q = kept_quads(m);
  if (q.nb_quads() == 0) return 0;
  std::unordered_set<EdgeKey, EdgeKeyHash> quad_edges, constrained;
  for (int k = 0; k < q.nb_quads(); ++k)
    for (int j = 0; j < 4; ++j)
      quad_edges.insert(edge_key(q.quads[4 * k + j], q.quads[4 * k + (j + 1) % 4]));
  for (int e = 0; e < m.nb_edges(); ++e)
    constrained.insert(edge_key(m.edges[2 * e], m.edges[2 * e + 1]));
  const bool tags = m.edge_tags.size() == m.edge_curve.size();
  int added = 0;
  for (int t = 0; t < m.nb_tris(); ++t) {
    const int* v = &m.tris[3 * t];
    if (v[0] < 0) continue;
    for (int e = 0; e < 3; ++e) {
      if (m.adj[3 * t + e] >= 0) continue;
      const int a = v[(e + 1) % 3], b = v[(e + 2) % 3];
      const EdgeKey key = edge_key(a, b);
      if (!quad_edges.count(key) || !constrained.insert(key).second) continue;
      m.edges.insert(m.edges.end(), {a, b});
      m.edge_curve.push_back(-1 - m.tri_region[t]);
      if (tags) m.edge_tags.push_back(0);
      ++added;
    }
  }
  return added;
}

}  // namespace cvtmesh
