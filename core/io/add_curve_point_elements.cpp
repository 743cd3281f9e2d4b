#include "core/io/add_curve_point_elements.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace cvtmesh {

long add_curve_point_elements(MeshData& data) {
  ModelInfo& info = data.model();
  const std::vector<VertexClass>& vclass = data.dim == 3 ? data.tet.vclass : data.tri.vclass;
  std::set<int> points_with, curves_with;  // entities that have point / line elements
  for (const ElementBlock& b : info.extra) {
    if (b.dim == 0 && !b.tags.empty()) points_with.insert(b.entity);
    if (b.dim == 1 && !b.tags.empty()) curves_with.insert(b.entity);
  }
  if (data.dim == 2)
    for (int c : data.tri.edge_curve) curves_with.insert(c);
  long added = 0;
  std::map<int, ElementBlock> points;
  for (std::size_t v = 0; v < vclass.size(); ++v) {
    if (vclass[v].dim != 0 || points_with.count(vclass[v].entity)) continue;
    ElementBlock& b = points[vclass[v].entity];
    b.dim = 0;
    b.entity = vclass[v].entity;
    b.gmsh_type = 15;
    b.nodes.push_back(static_cast<int>(v));
  }
  std::map<int, ElementBlock> lines;
  if (data.dim == 3) {
    // The end points of each curve.
    std::map<int, std::vector<int>> ends;
    for (const ModelEntity& e : info.entities)
      if (e.dim == 1)
        for (int p : e.boundary) ends[e.tag].push_back(std::abs(p));
    auto bounds = [&](int curve, int point) {
      auto it = ends.find(curve);
      return it != ends.end() &&
             std::find(it->second.begin(), it->second.end(), point) != it->second.end();
    };
    const TetMesh& m = data.tet;
    std::set<int> curves_with_vertices;
    for (const VertexClass& c : m.vclass)
      if (c.dim == 1) curves_with_vertices.insert(c.entity);
    std::set<std::pair<int, int>> seen;
    for (int f = 0; f < m.nb_tris(); ++f) {
      const int* t = &m.tris[3 * f];
      if (t[0] < 0) continue;
      for (int k = 0; k < 3; ++k) {
        int a = t[k], b = t[(k + 1) % 3];
        if (a > b) std::swap(a, b);
        if (!seen.insert({a, b}).second) continue;
        const VertexClass ca = m.vclass[a], cb = m.vclass[b];
        if (ca.dim > 1 || cb.dim > 1) continue;
        int curve = 0;
        if (ca.dim == 1 && cb.dim == 1) {
          if (ca.entity == cb.entity) curve = ca.entity;
        } else if (ca.dim == 1 || cb.dim == 1) {
          const VertexClass on = ca.dim == 1 ? ca : cb, end = ca.dim == 1 ? cb : ca;
          if (bounds(on.entity, end.entity)) curve = on.entity;
        } else {
          // Both ends on points: the first curve of one segment between them.
          for (const auto& [c, e] : ends)
            if (!curves_with_vertices.count(c) && bounds(c, ca.entity) && bounds(c, cb.entity)) {
              curve = c;
              break;
            }
        }
        if (curve == 0 || curves_with.count(curve)) continue;
        ElementBlock& l = lines[curve];
        l.dim = 1;
        l.entity = curve;
        l.gmsh_type = 1;
        l.nodes.insert(l.nodes.end(), {a, b});
      }
    }
  }
  for (auto* blocks : {&points, &lines})
    for (auto& [entity, b] : *blocks) {
      added += static_cast<long>(b.nodes.size()) / (b.gmsh_type == 15 ? 1 : 2);
      b.tags.assign(b.nodes.size() / (b.gmsh_type == 15 ? 1 : 2), 0);
      info.extra.push_back(std::move(b));
    }
  return added;
}

}  // namespace cvtmesh
