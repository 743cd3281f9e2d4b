// Test-only: a MeshData in a form that compares exactly and independently of the order in which
// a reader returns nodes and elements (keyed by the original Gmsh tags).
#pragma once
#include <algorithm>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "core/mesh/mesh_data.h"

namespace cvtmesh::testing {

struct MeshCanon {
  int dim = 0;
  // node tag -> (x, y, z, classification dim, classification entity)
  std::map<std::size_t, std::tuple<double, double, double, int, int>> nodes;
  // element tag -> (entity, node tags in order): main simplices, facets, extra blocks
  std::map<std::size_t, std::pair<int, std::vector<std::size_t>>> cells, facets, extra;
  std::map<std::pair<int, int>, std::vector<int>> entities;  // (dim, tag) -> boundary
  std::map<std::pair<int, int>, std::pair<std::string, std::vector<int>>> groups;
  bool operator==(const MeshCanon& o) const {
    return dim == o.dim && nodes == o.nodes && cells == o.cells && facets == o.facets &&
           extra == o.extra && entities == o.entities && groups == o.groups;
  }
};

inline MeshCanon canon(const MeshData& d) {
  MeshCanon c;
  c.dim = d.dim;
  const bool three = d.dim == 3;
  const auto& ntags = three ? d.tet.node_tags : d.tri.node_tags;
  const auto& vclass = three ? d.tet.vclass : d.tri.vclass;
  const int nv = three ? d.tet.nb_vertices() : d.tri.nb_vertices();
  for (int v = 0; v < nv; ++v) {
    const double x = three ? d.tet.point(v)[0] : d.tri.point(v)[0];
    const double y = three ? d.tet.point(v)[1] : d.tri.point(v)[1];
    const double z = three ? d.tet.point(v)[2] : d.tri.z0;
    c.nodes[ntags.at(v)] = {x, y, z, vclass.at(v).dim, vclass.at(v).entity};
  }
  auto add = [&](auto& out, const std::vector<int>& conn, int npe, const std::vector<int>& ent,
                 const std::vector<std::size_t>& tags, const std::vector<int>* flip) {
    for (std::size_t e = 0; e < ent.size(); ++e) {
      std::vector<std::size_t> n;
      for (int k = 0; k < npe; ++k) n.push_back(ntags.at(conn[npe * e + k]));
      // 2D surfaces stored counter-clockwise but clockwise in the file: compare as in the file.
      if (flip && std::find(flip->begin(), flip->end(), ent[e]) != flip->end())
        std::swap(n[1], n[2]);
      out[tags.at(e)] = {ent[e], n};
    }
  };
  if (three) {
    add(c.cells, d.tet.tets, 4, d.tet.tet_region, d.tet.tet_tags, nullptr);
    add(c.facets, d.tet.tris, 3, d.tet.tri_surface, d.tet.tri_tags, nullptr);
  } else {
    add(c.cells, d.tri.tris, 3, d.tri.tri_region, d.tri.tri_tags, &d.tri.cw_surfaces);
    add(c.facets, d.tri.edges, 2, d.tri.edge_curve, d.tri.edge_tags, nullptr);
  }
  for (const auto& b : d.model().extra) {
    const std::size_t npe = b.tags.empty() ? 0 : b.nodes.size() / b.tags.size();
    for (std::size_t e = 0; e < b.tags.size(); ++e) {
      std::vector<std::size_t> n;
      for (std::size_t k = 0; k < npe; ++k) n.push_back(ntags.at(b.nodes[npe * e + k]));
      c.extra[b.tags[e]] = {b.entity, n};
    }
  }
  for (const auto& e : d.model().entities) c.entities[{e.dim, e.tag}] = e.boundary;
  for (const auto& g : d.model().groups) c.groups[{g.dim, g.tag}] = {g.name, g.entities};
  return c;
}

}  // namespace cvtmesh::testing
