#include "core/mesh/pin_vertices.h"

#include <unordered_set>

namespace cvtmesh {

namespace {

int pin_marked(std::vector<VertexClass>& vclass, const std::vector<char>& pin) {
  int n = 0;
  for (std::size_t v = 0; v < vclass.size(); ++v) {
    VertexClass& c = vclass[v];
    if (!pin[v] || c.entity < 0) continue;
    c = VertexClass{0, -1 - (4 * c.entity + c.dim)};
    ++n;
  }
  return n;
}

void unpin_marked(std::vector<VertexClass>& vclass) {
  for (VertexClass& c : vclass)
    if (c.entity < 0) {
      const int x = -1 - c.entity;
      c = VertexClass{static_cast<std::int8_t>(x % 4), x / 4};
    }
}

}  // namespace

int pin_vertices(TetMesh& m) {
  std::vector<char> pin(m.nb_vertices(), 0);
  // Points and lines (Gmsh's curves, dim < 2) lie on the boundary's corners and curves, which the
  // classification already holds (a free boundary slides curve vertices along them, and the line
  // elements follow); only their vertices off every boundary triangle (an embedded curve) are
  // pinned. Every vertex of a kept cell, quadrangle or loose triangle is.
  std::vector<char> on_boundary(m.nb_vertices(), 0);
  for (int v : m.tris) on_boundary[v] = 1;
  for (const ElementBlock& b : m.model.extra)
    for (int v : b.nodes) pin[v] |= b.dim >= 2 || !on_boundary[v];
  if (!m.model.periodic.empty() && !m.node_tags.empty()) {
    std::unordered_set<std::size_t> periodic;
    for (const PeriodicLink& l : m.model.periodic) {
      periodic.insert(l.node_tags.begin(), l.node_tags.end());
      periodic.insert(l.master_node_tags.begin(), l.master_node_tags.end());
    }
    for (int v = 0; v < m.nb_vertices(); ++v)
      if (periodic.count(m.node_tags[v])) pin[v] = 1;
  }
  return pin_marked(m.vclass, pin);
}

void unpin_vertices(TetMesh& m) {
  unpin_marked(m.vclass);
}

int pin_vertices(TriMesh2& m) {
  std::vector<char> pin(m.nb_vertices(), 0), on_edge(m.nb_vertices(), 0);
  for (int v : m.edges) on_edge[v] = 1;
  for (const ElementBlock& b : m.model.extra)
    for (int v : b.nodes) pin[v] |= b.dim >= 2 || !on_edge[v];
  return pin_marked(m.vclass, pin);
}

void unpin_vertices(TriMesh2& m) {
  unpin_marked(m.vclass);
}

}  // namespace cvtmesh
