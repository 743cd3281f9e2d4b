#include "core/io/gmsh_partition_map.h"

#include <gmsh.h>

#include <algorithm>
#include <set>

#include "core/util/error.h"

namespace cvtmesh {

GmshDimTag GmshPartitionMap::element_owner(int dim, int tag) const {
  auto it = roles.find({dim, tag});
  if (it == roles.end()) return {dim, tag};
  return it->second.elements ? it->second.parent : GmshDimTag{-1, -1};
}

GmshDimTag GmshPartitionMap::node_owner(int dim, int tag) const {
  auto it = roles.find({dim, tag});
  if (it == roles.end() || it->second.parent.first < 0) return {dim, tag};
  return it->second.parent;
}

void GmshPartitionMap::map_groups(std::vector<PhysicalGroup>& groups) const {
  if (!partitioned()) return;
  for (PhysicalGroup& g : groups) {
    std::vector<int> model;
    for (int e : g.entities) {
      const GmshDimTag owner = element_owner(g.dim, e);
      if (owner.first == g.dim &&
          std::find(model.begin(), model.end(), owner.second) == model.end())
        model.push_back(owner.second);
    }
    g.entities = std::move(model);
  }
  groups.erase(std::remove_if(groups.begin(), groups.end(),
                              [](const PhysicalGroup& g) { return g.entities.empty(); }),
               groups.end());
}

GmshPartitionMap read_gmsh_partition_map(const std::string& what, int file_parts) {
  GmshPartitionMap map;
  gmsh::vectorpair ents;
  gmsh::model::getEntities(ents);
  std::map<GmshDimTag, GmshDimTag> parent;  // partition entity -> its parent as Gmsh gives it
  int top = -1;                             // the highest dimension of a partition entity
  for (const auto& [d, t] : ents) {
    std::string type;
    gmsh::model::getType(d, t, type);
    GmshPartitionMap::Role r;
    r.ghost = type.rfind("Ghost", 0) == 0;
    if (!r.ghost && type.rfind("Partition", 0) != 0) continue;
    std::vector<int> parts;
    gmsh::model::getPartitions(d, t, parts);
    for (int p : parts) map.partitioning.nb_parts = std::max(map.partitioning.nb_parts, p);
    if (parts.size() == 1) r.part = parts[0];
    if (r.ghost) {
      map.partitioning.ghost_cells = true;
    } else {
      int pd = -1, pt = -1;
      gmsh::model::getParent(d, t, pd, pt);
      parent[{d, t}] = {pd, pt};
      top = std::max(top, d);
    }
    map.roles[{d, t}] = r;
  }
  if (map.roles.empty()) return map;
  // Parents, resolved to a model entity (a partition entity's parent is one in Gmsh 4.8; a chain
  // is followed, a loop or a missing parent leaves the entity its own).
  for (auto& [key, r] : map.roles) {
    if (r.ghost) continue;
    GmshDimTag p = parent[key];
    for (int guard = 0; guard < 8 && map.roles.count(p) && !map.roles[p].ghost; ++guard)
      p = parent[p];
    if (p.first < 0 || map.roles.count(p)) {
      // No parent: the entity is kept as one of the model.
      r.parent = key;
      r.elements = true;
      continue;
    }
    r.parent = p;
    r.elements = p.first == key.first;  // else an interface between parts inside `p`
  }
  for (auto it = map.roles.begin(); it != map.roles.end();) {
    // Partition entities without a parent are the model's own.
    if (!it->second.ghost && it->second.parent == it->first)
      it = map.roles.erase(it);
    else
      ++it;
  }
  // With Mesh.PartitionCreateTopology the cells' partition entities have boundaries.
  for (const auto& [key, r] : map.roles) {
    if (r.ghost || key.first != top || map.partitioning.topology) continue;
    gmsh::vectorpair b;
    gmsh::model::getBoundary({key}, b, false, false, false);
    map.partitioning.topology = !b.empty();
  }
  // One file of a mesh split one file per part holds the cells of its own part only (and the
  // interfaces it shares with the others, which name them).
  map.partitioning.nb_parts = std::max(map.partitioning.nb_parts, file_parts);
  std::set<int> with_cells;
  for (const auto& [key, r] : map.roles) {
    if (r.ghost || !r.elements || key.first != top || r.part <= 0) continue;
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, key.first, key.second);
    if (!types.empty()) with_cells.insert(r.part);
  }
  if (!with_cells.empty() && static_cast<int>(with_cells.size()) < map.partitioning.nb_parts) {
    std::string held;
    for (int p : with_cells) held += (held.empty() ? "" : ", ") + std::to_string(p);
    throw InputError(
        what + " holds part" + (with_cells.size() > 1 ? "s " : " ") + held + " of " +
        std::to_string(map.partitioning.nb_parts) +
        " of a partitioned mesh saved one file per part (gmsh -part_split, "
        "Mesh.PartitionSplitMeshFiles = 1): not the whole mesh, and cvtmesh does not read the "
        "parts' files together (Gmsh 4.8 merging them repeats the nodes and elements the parts "
        "share); save the partitioned mesh as one file (without -part_split) and optimize that");
  }
  return map;
}

}  // namespace cvtmesh
