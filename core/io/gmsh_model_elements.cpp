#include "core/io/gmsh_model_elements.h"

#include <gmsh.h>

#include <algorithm>
#include <functional>
#include <unordered_map>
#include <map>
#include <numeric>

namespace cvtmesh {
namespace {

// A file that repeats its mesh (a view appended with the mesh written again: read_msh_format.h)
// comes back from Gmsh 4.8 with every element of an entity twice, although it logs them as
// skipped: a repeat of a tag with the same nodes is dropped. (A repeat with other nodes stays,
// for the reader's checks to refuse.) Tags in increasing order, the usual case, hold no repeat.
void drop_repeated_elements(std::vector<GmshEntityElements>& out) {
  for (GmshEntityElements& e : out)
    for (std::size_t k = 0; k < e.types.size(); ++k) {
      std::vector<std::size_t>& tags = e.tags[k];
      if (tags.empty() ||
          std::adjacent_find(tags.begin(), tags.end(), std::greater_equal<>()) == tags.end())
        continue;
      const std::size_t n = e.nodes[k].size() / tags.size();
      std::unordered_map<std::size_t, std::size_t> first;
      std::vector<std::size_t> kept_tags, kept_nodes;
      std::vector<int> kept_parts;
      const bool parts = !e.parts.empty() && e.parts[k].size() == tags.size();
      for (std::size_t i = 0; i < tags.size(); ++i) {
        const auto [it, fresh] = first.emplace(tags[i], i);
        if (!fresh &&
            std::equal(&e.nodes[k][n * i], &e.nodes[k][n * i] + n, &e.nodes[k][n * it->second]))
          continue;
        kept_tags.push_back(tags[i]);
        kept_nodes.insert(kept_nodes.end(), &e.nodes[k][n * i], &e.nodes[k][n * i] + n);
        if (parts) kept_parts.push_back(e.parts[k][i]);
      }
      tags = std::move(kept_tags);
      e.nodes[k] = std::move(kept_nodes);
      if (parts) e.parts[k] = std::move(kept_parts);
    }
}

}  // namespace

std::vector<GmshEntityElements> read_model_elements(
    const std::vector<std::pair<int, int>>& entities, const GmshPartitionMap& map) {
  std::vector<GmshEntityElements> out;
  std::map<GmshDimTag, std::size_t> block;  // model entity -> its position in out
  for (const auto& [d, t] : entities) {
    const GmshDimTag owner = map.element_owner(d, t);
    if (owner.first < 0) continue;
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, d, t);
    if (types.empty()) continue;
    auto [it, fresh] = block.emplace(owner, out.size());
    if (fresh) {
      out.emplace_back();
      out.back().dim = owner.first;
      out.back().tag = owner.second;
    }
    GmshEntityElements& e = out[it->second];
    const auto role = map.roles.find({d, t});
    const int part = role == map.roles.end() ? 0 : role->second.part;
    for (std::size_t k = 0; k < types.size(); ++k) {
      const auto at = std::find(e.types.begin(), e.types.end(), types[k]);
      if (map.partitioned()) {
        const std::size_t i = at - e.types.begin();
        if (at == e.types.end()) e.parts.emplace_back();
        e.parts[i].insert(e.parts[i].end(), tags[k].size(), part);
      }
      if (at == e.types.end()) {
        e.types.push_back(types[k]);
        e.tags.push_back(std::move(tags[k]));
        e.nodes.push_back(std::move(nodes[k]));
        continue;
      }
      const std::size_t i = at - e.types.begin();
      e.tags[i].insert(e.tags[i].end(), tags[k].begin(), tags[k].end());
      e.nodes[i].insert(e.nodes[i].end(), nodes[k].begin(), nodes[k].end());
    }
  }
  drop_repeated_elements(out);
  if (!map.partitioned()) return out;
  // The model entities in the order of `entities` (where they are listed), as unpartitioned.
  std::map<GmshDimTag, std::size_t> position;
  for (std::size_t i = 0; i < entities.size(); ++i) position.emplace(entities[i], i);
  auto rank = [&](const GmshEntityElements& e) {
    auto it = position.find({e.dim, e.tag});
    return it == position.end() ? entities.size() : it->second;
  };
  std::stable_sort(
      out.begin(), out.end(),
      [&](const GmshEntityElements& a, const GmshEntityElements& b) { return rank(a) < rank(b); });
  // The parts' elements of one entity back in the order of their tags.
  for (GmshEntityElements& e : out)
    for (std::size_t k = 0; k < e.types.size(); ++k) {
      std::vector<std::size_t>& tags = e.tags[k];
      if (std::is_sorted(tags.begin(), tags.end()) || tags.empty()) continue;
      const std::size_t n = e.nodes[k].size() / tags.size();
      std::vector<std::size_t> order(tags.size());
      std::iota(order.begin(), order.end(), std::size_t{0});
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t a, std::size_t b) { return tags[a] < tags[b]; });
      std::vector<std::size_t> sorted_tags(tags.size()), sorted_nodes(e.nodes[k].size());
      std::vector<int> sorted_parts(tags.size());
      for (std::size_t i = 0; i < order.size(); ++i) {
        sorted_tags[i] = tags[order[i]];
        sorted_parts[i] = e.parts[k][order[i]];
        std::copy_n(&e.nodes[k][n * order[i]], n, &sorted_nodes[n * i]);
      }
      tags = std::move(sorted_tags);
      e.nodes[k] = std::move(sorted_nodes);
      e.parts[k] = std::move(sorted_parts);
    }
  return out;
}

}  // namespace cvtmesh
