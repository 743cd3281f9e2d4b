#include "core/mesh/keep_free_curve_lines.h"

#include <map>
#include <unordered_set>

#include "core/mesh/face_key.h"

namespace cvtmesh {

int keep_free_curve_lines(TriMesh2& m) {
  std::unordered_set<EdgeKey, EdgeKeyHash> tri_edges;
  for (int t = 0; t < m.nb_tris(); ++t) {
    const int* v = &m.tris[3 * t];
    if (v[0] < 0) continue;
    for (int k = 0; k < 3; ++k) tri_edges.insert(edge_key(v[k], v[(k + 1) % 3]));
  }
  const bool tags = m.edge_tags.size() == m.edge_curve.size();
  std::map<int, std::size_t> block_of;  // curve -> its block in m.model.extra
  std::size_t kept = 0;
  int moved = 0;
  for (int e = 0; e < m.nb_edges(); ++e) {
    const int a = m.edges[2 * e], b = m.edges[2 * e + 1];
    if (!tri_edges.count(edge_key(a, b))) {
      auto [it, fresh] = block_of.emplace(m.edge_curve[e], m.model.extra.size());
      if (fresh) {
        ElementBlock blk;
        blk.dim = 1;
        blk.entity = m.edge_curve[e];
        blk.gmsh_type = 1;
        m.model.extra.push_back(blk);
      }
      ElementBlock& blk = m.model.extra[it->second];
      blk.nodes.insert(blk.nodes.end(), {a, b});
      blk.tags.push_back(tags ? m.edge_tags[e] : 0);
      ++moved;
      continue;
    }
    m.edges[2 * kept] = a;
    m.edges[2 * kept + 1] = b;
    m.edge_curve[kept] = m.edge_curve[e];
    if (tags) m.edge_tags[kept] = m.edge_tags[e];
    ++kept;
  }
  m.edges.resize(2 * kept);
  m.edge_curve.resize(kept);
  if (tags) m.edge_tags.resize(kept);
  return moved;
}

}  // namespace cvtmesh
