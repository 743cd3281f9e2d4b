#include "core/io/gmsh_missing_facets.h"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <unordered_map>
#include <vector>

namespace cvtmesh {
namespace {

using Key = std::array<std::size_t, 3>;  // sorted node tags (third is 0 for an edge)

struct KeyHash {
  std::size_t operator()(const Key& k) const {
    std::size_t h = k[0];
    h = h * 0x9E3779B97F4A7C15ULL ^ k[1];
    h = h * 0x9E3779B97F4A7C15ULL ^ k[2];
    return h ^ (h >> 29);
  }
};

struct Facet {
  int count = 0;
  int cell_entity[2] = {0, 0};
  std::array<std::size_t, 3> nodes{};  // as found in the first cell
};

}  // namespace

long add_missing_facets(int dim) {
  if (dim != 2 && dim != 3) return 0;
  const int cell_type = dim == 3 ? 4 : 2, facet_type = dim == 3 ? 2 : 1;
  const int npf = dim;  // nodes per facet
  static const int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  static const int kEdge[3][2] = {{1, 2}, {2, 0}, {0, 1}};
  auto key_of = [&](const std::size_t* n) {
    Key k{n[0], n[1], npf == 3 ? n[2] : 0};
    if (k[0] > k[1]) std::swap(k[0], k[1]);
    if (npf == 3) {
      if (k[1] > k[2]) std::swap(k[1], k[2]);
      if (k[0] > k[1]) std::swap(k[0], k[1]);
    }
    return k;
  };

  std::unordered_map<Key, Facet, KeyHash> facets;
  gmsh::vectorpair cells_ents;
  gmsh::model::getEntities(cells_ents, dim);
  for (const auto& [d, ent] : cells_ents) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(cell_type, tags, nodes, ent);
    const std::size_t npe = dim + 1;
    for (std::size_t e = 0; e < tags.size(); ++e) {
      const std::size_t* c = &nodes[npe * e];
      for (std::size_t f = 0; f < npe; ++f) {
        std::size_t n[3] = {0, 0, 0};
        for (int k = 0; k < npf; ++k) n[k] = dim == 3 ? c[kFace[f][k]] : c[kEdge[f][k]];
        Facet& fc = facets[key_of(n)];
        if (fc.count < 2) fc.cell_entity[fc.count] = ent;
        if (fc.count == 0) fc.nodes = {n[0], n[1], n[2]};
        ++fc.count;
      }
    }
  }
  if (facets.empty()) return 0;
  // Facets that are elements already; the largest element tag.
  std::size_t max_tag = 0;
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> etags, enodes;
    gmsh::model::mesh::getElements(types, etags, enodes, -1, -1);
    for (std::size_t k = 0; k < types.size(); ++k) {
      for (std::size_t t : etags[k]) max_tag = std::max(max_tag, t);
      if (types[k] != facet_type) continue;
      for (std::size_t e = 0; e < etags[k].size(); ++e) {
        auto it = facets.find(key_of(&enodes[k][npf * e]));
        if (it != facets.end()) it->second.count = -1;  // present
      }
    }
  }
  // Node classification on the lower-dimensional entities.
  std::unordered_map<std::size_t, std::pair<int, int>> where;
  for (int d = 0; d < dim; ++d) {
    gmsh::vectorpair ents;
    gmsh::model::getEntities(ents, d);
    for (const auto& [dd, t] : ents) {
      std::vector<std::size_t> tags;
      std::vector<double> xyz, par;
      gmsh::model::mesh::getNodes(tags, xyz, par, dd, t, false, false);
      for (std::size_t n : tags) where[n] = {dd, t};
    }
  }
  std::map<int, std::vector<int>> bounding;              // cell entity -> facet entities
  std::map<int, std::set<std::pair<int, int>>> closure;  // facet entity -> entities below it
  auto facets_of = [&](int cell_ent) -> const std::vector<int>& {
    auto it = bounding.find(cell_ent);
    if (it != bounding.end()) return it->second;
    gmsh::vectorpair b;
    gmsh::model::getBoundary({{dim, cell_ent}}, b, false, false, false);
    std::vector<int>& v = bounding[cell_ent];
    for (const auto& p : b) v.push_back(std::abs(p.second));
    return v;
  };
  auto closure_of = [&](int facet_ent) -> const std::set<std::pair<int, int>>& {
    auto it = closure.find(facet_ent);
    if (it != closure.end()) return it->second;
    std::set<std::pair<int, int>>& s = closure[facet_ent];
    gmsh::vectorpair frontier = {{dim - 1, facet_ent}};
    while (!frontier.empty()) {
      gmsh::vectorpair b;
      gmsh::model::getBoundary(frontier, b, false, false, false);
      frontier.clear();
      for (auto p : b) {
        p.second = std::abs(p.second);
        if (s.insert(p).second && p.first > 0) frontier.push_back(p);
      }
    }
    return s;
  };

  std::map<int, std::pair<std::vector<std::size_t>, std::vector<std::size_t>>> added;
  std::vector<std::size_t> unplaced;  // nodes of facets without any classification to go by
  long nb = 0;
  for (const auto& [key, fc] : facets) {
    const bool boundary = fc.count == 1;
    const bool interface = fc.count == 2 && fc.cell_entity[0] != fc.cell_entity[1];
    if (!boundary && !interface) continue;
    int entity = 0;
    for (int k = 0; k < npf && !entity; ++k) {
      auto it = where.find(fc.nodes[k]);
      if (it != where.end() && it->second.first == dim - 1) entity = it->second.second;
    }
    if (!entity) {
      // All nodes on lower entities: a boundary entity of the cell(s) whose closure holds them.
      std::vector<int> candidates = facets_of(fc.cell_entity[0]);
      if (interface) {
        const std::vector<int>& other = facets_of(fc.cell_entity[1]);
        candidates.erase(
            std::remove_if(
                candidates.begin(), candidates.end(),
                [&](int s) { return std::find(other.begin(), other.end(), s) == other.end(); }),
            candidates.end());
      }
      for (int s : candidates) {
        const auto& cl = closure_of(s);
        bool all = true;
        for (int k = 0; k < npf; ++k) {
          auto it = where.find(fc.nodes[k]);
          all &= it != where.end() && cl.count(it->second) > 0;
        }
        if (all) {
          entity = s;
          break;
        }
      }
    }
    if (!entity) {
      unplaced.insert(unplaced.end(), fc.nodes.begin(), fc.nodes.begin() + npf);
      continue;
    }
    auto& [tags, nodes] = added[entity];
    tags.push_back(++max_tag);
    nodes.insert(nodes.end(), fc.nodes.begin(), fc.nodes.begin() + npf);
    ++nb;
  }
  for (const auto& [ent, b] : added)
    gmsh::model::mesh::addElementsByType(ent, facet_type, b.first, b.second);
  if (!unplaced.empty()) {
    // A mesh without lower-dimensional entities (only tets, say): the boundary becomes a new
    // surface and its nodes, so far classified inside the volume, are moved onto it.
    gmsh::vectorpair lower;
    gmsh::model::getEntities(lower, dim - 1);
    int tag = 0;
    for (const auto& p : lower) tag = std::max(tag, p.second);
    tag = gmsh::model::addDiscreteEntity(dim - 1, tag + 1);
    std::vector<std::size_t> tags(unplaced.size() / npf);
    for (auto& t : tags) t = ++max_tag;
    gmsh::model::mesh::addElementsByType(tag, facet_type, tags, unplaced);
    gmsh::model::mesh::reclassifyNodes();
    nb += static_cast<long>(tags.size());
  }
  return nb;
}

}  // namespace cvtmesh
