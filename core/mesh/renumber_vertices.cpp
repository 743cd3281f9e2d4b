#include "core/mesh/renumber_vertices.h"

#include <unordered_map>

#include "core/mesh/build_adjacency.h"

namespace cvtmesh {

void permute_vertices(TetMesh& m, const std::vector<int>& new_id) {
  const int nv = m.nb_vertices();
  std::vector<double> xyz(m.xyz.size());
  std::vector<VertexClass> vc(m.vclass.size());
  std::vector<std::size_t> tags(m.node_tags.size());
  for (int v = 0; v < nv; ++v) {
    const int w = new_id[v];
    for (int d = 0; d < 3; ++d) xyz[3 * w + d] = m.xyz[3 * v + d];
    if (!vc.empty()) vc[w] = m.vclass[v];
    if (!tags.empty()) tags[w] = m.node_tags[v];
  }
  m.xyz = std::move(xyz);
  m.vclass = std::move(vc);
  m.node_tags = std::move(tags);
  for (int& v : m.tets)
    if (v >= 0) v = new_id[v];
  for (int& v : m.tris) v = new_id[v];
  for (auto& b : m.model.extra)
    for (int& v : b.nodes) v = new_id[v];
  // The adjacency (tet, local face) does not depend on the vertex ids: kept if it was built.
  if (m.adj.size() != m.tets.size()) build_adjacency(m);
}

void renumber_vertices_like(TetMesh& mesh, const TetMesh& ref) {
  if (mesh.node_tags.empty() || ref.node_tags.empty()) return;
  std::unordered_map<std::size_t, int> ref_index;
  for (int i = 0; i < static_cast<int>(ref.node_tags.size()); ++i)
    ref_index.emplace(ref.node_tags[i], i);
  const int nv = mesh.nb_vertices();
  std::vector<int> new_id(nv, -1);
  std::vector<char> taken(nv, 0);
  for (int v = 0; v < nv; ++v) {
    auto it = ref_index.find(mesh.node_tags[v]);
    if (it != ref_index.end() && it->second < nv && !taken[it->second]) {
      new_id[v] = it->second;
      taken[it->second] = 1;
    }
  }
  int next = 0;
  for (int v = 0; v < nv; ++v) {
    if (new_id[v] >= 0) continue;
    while (taken[next]) ++next;
    new_id[v] = next;
    taken[next] = 1;
  }
  permute_vertices(mesh, new_id);
}

}  // namespace cvtmesh
