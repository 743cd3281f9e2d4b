// Test-only: what Gmsh itself sees in a file (through the Gmsh API), in a form that compares
// exactly: entities with boundaries, physical groups with names, nodes per entity with
// coordinates, elements per entity with tags and node tags, and the post-processing views.
#pragma once
#include <gmsh.h>

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "core/io/gmsh_session.h"

namespace cvtmesh::testing {

struct GmshDump {
  // (dim, tag) -> boundary tags (signed, as Gmsh reports them)
  std::map<std::pair<int, int>, std::vector<int>> entities;
  // (dim, tag) -> (name, entity tags)
  std::map<std::pair<int, int>, std::pair<std::string, std::vector<int>>> groups;
  // node tag -> (x, y, z, dim, entity): coordinates and classification
  std::map<std::size_t, std::tuple<double, double, double, int, int>> nodes;
  // element tag -> (gmsh type, entity dim, entity tag, node tags)
  std::map<std::size_t, std::tuple<int, int, int, std::vector<std::size_t>>> elements;
  // view name -> element tag -> value (first component, step 0)
  std::map<std::string, std::map<std::size_t, double>> views;
};

inline GmshDump gmsh_dump(const std::string& path) {
  GmshSession session;
  GmshDump d;
  std::vector<int> before;
  gmsh::view::getTags(before);
  gmsh::open(path);
  gmsh::vectorpair ents;
  gmsh::model::getEntities(ents);
  for (const auto& [dim, tag] : ents) {
    std::vector<int> b;
    if (dim > 0) {
      gmsh::vectorpair bd;
      gmsh::model::getBoundary({{dim, tag}}, bd, false, true, false);
      for (const auto& p : bd) b.push_back(p.second);
    }
    d.entities[{dim, tag}] = b;
    std::vector<std::size_t> ntags;
    std::vector<double> xyz, par;
    gmsh::model::mesh::getNodes(ntags, xyz, par, dim, tag, false, false);
    for (std::size_t i = 0; i < ntags.size(); ++i)
      d.nodes[ntags[i]] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2], dim, tag};
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> etags, enodes;
    gmsh::model::mesh::getElements(types, etags, enodes, dim, tag);
    for (std::size_t k = 0; k < types.size(); ++k) {
      const std::size_t npe = etags[k].empty() ? 0 : enodes[k].size() / etags[k].size();
      for (std::size_t e = 0; e < etags[k].size(); ++e)
        d.elements[etags[k][e]] = {types[k], dim, tag,
                                   std::vector<std::size_t>(enodes[k].begin() + npe * e,
                                                            enodes[k].begin() + npe * (e + 1))};
    }
  }
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  for (const auto& [dim, tag] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    std::vector<int> e;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, e);
    d.groups[{dim, tag}] = {name, e};
  }
  std::vector<int> after;
  gmsh::view::getTags(after);
  for (int v : after) {
    bool old = false;
    for (int b : before) old |= b == v;
    if (old) continue;
    std::string name, type;
    gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(v)) + "].Name", name);
    std::vector<std::size_t> tags;
    std::vector<std::vector<double>> data;
    double time = 0;
    int ncomp = 0;
    gmsh::view::getModelData(v, 0, type, tags, data, time, ncomp);
    auto& m = d.views[name];
    for (std::size_t i = 0; i < tags.size(); ++i) m[tags[i]] = data[i].empty() ? 0 : data[i][0];
    gmsh::view::remove(v);
  }
  gmsh::model::remove();
  return d;
}

}  // namespace cvtmesh::testing
