#include "core/mesh/extract_regions.h"

#include <algorithm>
#include <unordered_map>

#include "core/mesh/build_adjacency.h"
#include "core/mesh/face_key.h"

namespace cvtmesh {

RegionSubmesh extract_regions(const TetMesh& m, const std::vector<int>& regions) {
  std::vector<char> selected(m.nb_tets(), 0);
  for (int t = 0; t < m.nb_tets(); ++t)
    selected[t] = std::find(regions.begin(), regions.end(), m.tet_region[t]) != regions.end();
  return extract_tets(m, selected);
}

RegionSubmesh extract_tets(const TetMesh& m, const std::vector<char>& selected) {
  RegionSubmesh r;
  const int nt = m.nb_tets(), nv = m.nb_vertices();
  r.selected_tet.assign(nt, 0);
  std::vector<char> in_sel(nv, 0), in_other(nv, 0);
  for (int t = 0; t < nt; ++t) {
    if (m.tets[4 * t] < 0) continue;
    const bool sel = selected[t] != 0;
    r.selected_tet[t] = sel;
    for (int k = 0; k < 4; ++k) (sel ? in_sel : in_other)[m.tets[4 * t + k]] = 1;
  }
  // Vertices in parent order.
  std::vector<int> to_sub(nv, -1);
  for (int v = 0; v < nv; ++v)
    if (in_sel[v]) {
      to_sub[v] = static_cast<int>(r.to_parent.size());
      r.to_parent.push_back(v);
    }
  TetMesh& s = r.mesh;
  const int ns = static_cast<int>(r.to_parent.size());
  s.xyz.resize(3 * static_cast<std::size_t>(ns));
  s.vclass.resize(ns);
  s.node_tags.resize(ns);
  if (!m.node_tags.empty()) r.parent_tags.resize(ns);
  auto pin = [](VertexClass& c) {
    if (c.entity >= 0) c = VertexClass{0, -1 - (4 * c.entity + c.dim)};
  };
  for (int i = 0; i < ns; ++i) {
    const int v = r.to_parent[i];
    std::copy(m.point(v), m.point(v) + 3, s.point(i));
    s.vclass[i] = m.vclass[v];
    s.node_tags[i] = static_cast<std::size_t>(i) + 1;
    if (!m.node_tags.empty()) r.parent_tags[i] = m.node_tags[v];
    if (in_other[v]) {
      pin(s.vclass[i]);
      ++r.nb_interface;
    }
  }
  // Tets, in the parent's order.
  std::unordered_map<FaceKey, int, FaceKeyHash> face_count;
  for (int t = 0; t < nt; ++t) {
    if (!r.selected_tet[t]) continue;
    for (int k = 0; k < 4; ++k) s.tets.push_back(to_sub[m.tets[4 * t + k]]);
    s.tet_region.push_back(m.tet_region[t]);
    if (!m.tet_tags.empty()) s.tet_tags.push_back(m.tet_tags[t]);
    const int* tv = &s.tets[s.tets.size() - 4];
    for (const auto& f : kTetFace) ++face_count[face_key(tv[f[0]], tv[f[1]], tv[f[2]])];
  }
  // The parent's triangles on faces of selected tets.
  r.selected_tri.assign(m.nb_tris(), 0);
  int max_surface = 0;
  for (int f = 0; f < m.nb_tris(); ++f) {
    max_surface = std::max(max_surface, m.tri_surface[f]);
    const int a = to_sub[m.tris[3 * f]], b = to_sub[m.tris[3 * f + 1]],
              c = to_sub[m.tris[3 * f + 2]];
    if (a < 0 || b < 0 || c < 0) continue;
    auto it = face_count.find(face_key(a, b, c));
    if (it == face_count.end()) continue;
    r.selected_tri[f] = 1;
    s.tris.insert(s.tris.end(), {a, b, c});
    s.tri_surface.push_back(m.tri_surface[f]);
    if (!m.tri_tags.empty()) s.tri_tags.push_back(m.tri_tags[f]);
    it->second += 2;  // marks the face as carried (counts 1 or 2 become >= 3)
  }
  // Boundary faces of the selection without a triangle (an interface the model has no surface
  // for): constrained too, on a surface tag of their own, their vertices pinned.
  for (const auto& [k, n] : face_count) {
    if (n != 1) continue;
    s.tris.insert(s.tris.end(), k.begin(), k.end());
    s.tri_surface.push_back(max_surface + 1);
    if (!m.tri_tags.empty()) s.tri_tags.push_back(0);
    for (int v : k) pin(s.vclass[v]);
    ++r.nb_added_faces;
  }
  // Model data: entities, groups, periodic links; the extra blocks wholly inside.
  s.model = m.model;
  s.model.extra.clear();
  for (const ElementBlock& b : m.model.extra) {
    const int npe = b.tags.empty() ? 0 : static_cast<int>(b.nodes.size() / b.tags.size());
    ElementBlock sb = b;
    sb.tags.clear();
    sb.nodes.clear();
    sb.medit_refs.clear();
    for (std::size_t e = 0; e < b.tags.size(); ++e) {
      bool inside = true;
      for (int j = 0; j < npe; ++j) inside = inside && to_sub[b.nodes[e * npe + j]] >= 0;
      for (int j = 0; j < npe; ++j) {
        const int v = to_sub[b.nodes[e * npe + j]];
        if (v >= 0 && !inside) pin(s.vclass[v]);
        if (inside) sb.nodes.push_back(v);
      }
      if (!inside) continue;
      sb.tags.push_back(b.tags[e]);
      if (e < b.medit_refs.size()) sb.medit_refs.push_back(b.medit_refs[e]);
    }
    if (!sb.tags.empty()) s.model.extra.push_back(std::move(sb));
  }
  // Periodic links are by node tag, and the sub's tags are its own: their nodes are pinned here.
  if (!m.model.periodic.empty() && !m.node_tags.empty()) {
    std::unordered_map<std::size_t, int> by_tag;
    for (int i = 0; i < ns; ++i) by_tag.emplace(r.parent_tags[i], i);
    for (const PeriodicLink& l : m.model.periodic)
      for (const auto* tags : {&l.node_tags, &l.master_node_tags})
        for (std::size_t t : *tags)
          if (auto it = by_tag.find(t); it != by_tag.end()) pin(s.vclass[it->second]);
  }
  s.model.periodic.clear();
  build_adjacency(s);
  return r;
}

}  // namespace cvtmesh
