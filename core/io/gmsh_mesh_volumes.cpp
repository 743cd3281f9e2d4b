#include "core/io/gmsh_mesh_volumes.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>

#include "core/io/gmsh_surface.h"
#include "core/mesh/face_key.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

// The triangles (type 2) of every surface entity of the current model: node tags, 3 per
// triangle, and the entity of each.
struct Triangles {
  std::vector<std::size_t> nodes;
  std::vector<int> entity;
};

Triangles model_triangles() {
  Triangles t;
  gmsh::vectorpair surfaces;
  gmsh::model::getEntities(surfaces, 2);
  for (const auto& [d, s] : surfaces) {
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(2, tags, nodes, s);
    t.nodes.insert(t.nodes.end(), nodes.begin(), nodes.end());
    t.entity.insert(t.entity.end(), tags.size(), s);
  }
  return t;
}

// The triangles as a SurfaceMesh (dense vertex ids in the order of first use).
SurfaceMesh surface_of(const Triangles& t) {
  SurfaceMesh s;
  std::vector<std::size_t> tags;
  std::vector<double> xyz, par;
  gmsh::model::mesh::getNodes(tags, xyz, par, -1, -1, false, false);
  std::unordered_map<std::size_t, std::size_t> at;  // tag -> position in tags
  at.reserve(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i) at.emplace(tags[i], i);
  std::unordered_map<std::size_t, int> id;
  for (std::size_t n : t.nodes) {
    auto [it, fresh] = id.emplace(n, static_cast<int>(id.size()));
    if (fresh) {
      const double* p = &xyz[3 * at.at(n)];
      s.xyz.insert(s.xyz.end(), p, p + 3);
    }
    s.tris.push_back(it->second);
  }
  return s;
}

struct EntityCopy {
  int dim = 0, tag = 0;
  std::vector<int> boundary;
  std::vector<std::size_t> node_tags;
  std::vector<double> xyz;
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
};

struct GroupCopy {
  int dim = 0, tag = 0;
  std::string name;
  std::vector<int> entities;
};

}  // namespace

bool is_surface_mesh_of_volumes() {
  gmsh::vectorpair volumes;
  gmsh::model::getEntities(volumes, 3);
  for (const auto& [d, v] : volumes) {
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, 3, v);
    if (!types.empty()) return false;
  }
  const Triangles t = model_triangles();
  if (t.nodes.empty()) return false;
  if (!volumes.empty()) return true;
  const SurfaceMesh s = surface_of(t);
  double zmin = s.xyz[2], zmax = s.xyz[2], extent = 0;
  for (std::size_t v = 0; v < s.xyz.size() / 3; ++v) {
    zmin = std::min(zmin, s.xyz[3 * v + 2]);
    zmax = std::max(zmax, s.xyz[3 * v + 2]);
    for (int k = 0; k < 3; ++k) extent = std::max(extent, std::fabs(s.xyz[3 * v + k]));
  }
  if (zmax - zmin <= 1e-12 * std::max(extent, 1.0)) return false;
  return surface_closes_up(s);
}

std::vector<int> mesh_volumes_of_surface_mesh(const std::string& what, const ReadOptions& options) {
  // Everything below the volumes, copied.
  std::vector<EntityCopy> copies;
  for (int dim = 0; dim <= 2; ++dim) {
    gmsh::vectorpair ents;
    gmsh::model::getEntities(ents, dim);
    for (const auto& [d, t] : ents) {
      EntityCopy c;
      c.dim = d;
      c.tag = t;
      if (d > 0) {
        gmsh::vectorpair b;
        gmsh::model::getBoundary({{d, t}}, b, false, true, false);
        for (const auto& p : b) c.boundary.push_back(p.second);
      }
      std::vector<double> par;
      gmsh::model::mesh::getNodes(c.node_tags, c.xyz, par, d, t, false, false);
      gmsh::model::mesh::getElements(c.types, c.element_tags, c.element_nodes, d, t);
      for (int type : c.types)
        if (d == 2 && type != 2) {
          std::string name;
          int edim = 0, order = 0, nodes = 0, primary = 0;
          std::vector<double> local;
          gmsh::model::mesh::getElementProperties(type, name, edim, order, nodes, local, primary);
          throw InputError(what + ": a surface mesh without tetrahedra whose surface " +
                           std::to_string(t) + " holds '" + name +
                           "' elements: only linear triangles can bound the volumes cvtmesh has "
                           "Gmsh mesh; mesh the volumes first (gmsh -3)");
        }
      copies.push_back(std::move(c));
    }
  }
  std::vector<GroupCopy> groups;
  {
    gmsh::vectorpair g;
    gmsh::model::getPhysicalGroups(g);
    for (const auto& [d, t] : g) {
      GroupCopy c;
      c.dim = d;
      c.tag = t;
      gmsh::model::getPhysicalName(d, t, c.name);
      gmsh::model::getEntitiesForPhysicalGroup(d, t, c.entities);
      groups.push_back(std::move(c));
    }
  }
  // The volumes: the file's (one surface loop of all their boundary surfaces), or one per
  // closed shell that is not a cavity (a loop per shell: its own, then its cavities').
  std::vector<std::pair<int, std::vector<std::vector<int>>>> volumes;  // tag, loops
  {
    gmsh::vectorpair ents;
    gmsh::model::getEntities(ents, 3);
    for (const auto& [d, v] : ents) {
      gmsh::vectorpair b;
      gmsh::model::getBoundary({{3, v}}, b, false, false, false);
      std::vector<int> loop;
      for (const auto& p : b) loop.push_back(std::abs(p.second));
      if (loop.empty())
        throw InputError(what + ": volume " + std::to_string(v) +
                         " has no bounding surface: its inside cannot be meshed");
      volumes.push_back({v, {loop}});
    }
  }
  if (volumes.empty()) {
    const Triangles t = model_triangles();
    SurfaceMesh s = surface_of(t);
    orient_shells(s);
    int nb = 0;
    const std::vector<int> shell = shells_of(s, nb);
    std::vector<int> depth, parent;
    nest_shells(s, shell, nb, depth, parent);
    // A surface entity on several shells (a .ply2 or an .stl-like file: one surface for all) is
    // split, one discrete surface per shell: the first keeps its tag, and its physical groups
    // take the others. One with boundary curves is not split (they would be ambiguous).
    std::map<int, std::map<int, int>> piece;  // entity -> shell -> tag
    int next_tag = 0;
    for (const EntityCopy& c : copies)
      if (c.dim == 2) next_tag = std::max(next_tag, c.tag);
    for (std::size_t f = 0; f < shell.size(); ++f) {
      auto& of = piece[t.entity[f]];
      if (of.count(shell[f])) continue;
      of[shell[f]] = of.empty() ? t.entity[f] : ++next_tag;
    }
    std::vector<EntityCopy> pieces;
    for (EntityCopy& c : copies) {
      if (c.dim != 2 || piece[c.tag].size() < 2) continue;
      if (!c.boundary.empty())
        throw InputError(what + ": surface " + std::to_string(c.tag) +
                         " lies on several separate closed shells and has boundary curves: "
                         "cannot tell the volumes");
      const auto& of = piece[c.tag];
      // The entity's triangles are t's in order from the first of this entity.
      const std::size_t first =
          std::find(t.entity.begin(), t.entity.end(), c.tag) - t.entity.begin();
      std::map<int, EntityCopy> by_tag;
      for (const auto& [sh, tag] : of) {
        EntityCopy& e = by_tag[tag];
        e.dim = 2;
        e.tag = tag;
        e.types = {2};
        e.element_tags.resize(1);
        e.element_nodes.resize(1);
      }
      std::unordered_map<std::size_t, int> node_piece;
      for (std::size_t k = 0; k < c.element_tags[0].size(); ++k) {
        const int tag = of.at(shell[first + k]);
        EntityCopy& e = by_tag[tag];
        e.element_tags[0].push_back(c.element_tags[0][k]);
        for (int j = 0; j < 3; ++j) {
          const std::size_t n = c.element_nodes[0][3 * k + j];
          e.element_nodes[0].push_back(n);
          node_piece.emplace(n, tag);
        }
      }
      for (std::size_t i = 0; i < c.node_tags.size(); ++i) {
        auto it = node_piece.find(c.node_tags[i]);
        EntityCopy& e = by_tag[it == node_piece.end() ? c.tag : it->second];
        e.node_tags.push_back(c.node_tags[i]);
        e.xyz.insert(e.xyz.end(), &c.xyz[3 * i], &c.xyz[3 * i] + 3);
      }
      for (auto& g : groups)
        if (g.dim == 2 &&
            std::find(g.entities.begin(), g.entities.end(), c.tag) != g.entities.end())
          for (const auto& [sh, tag] : of)
            if (tag != c.tag) g.entities.push_back(tag);
      c = std::move(by_tag.at(c.tag));
      for (auto& [tag, e] : by_tag)
        if (tag != c.tag) pieces.push_back(std::move(e));
    }
    copies.insert(copies.end(), std::make_move_iterator(pieces.begin()),
                  std::make_move_iterator(pieces.end()));
    std::vector<std::set<int>> surfaces(nb);
    for (std::size_t f = 0; f < shell.size(); ++f)
      surfaces[shell[f]].insert(piece[t.entity[f]].at(shell[f]));
    int next = 0;
    for (int sh = 0; sh < nb; ++sh) {
      if (depth[sh] % 2) continue;
      std::vector<std::vector<int>> loops = {{surfaces[sh].begin(), surfaces[sh].end()}};
      for (int c = 0; c < nb; ++c)
        if (parent[c] == sh) loops.push_back({surfaces[c].begin(), surfaces[c].end()});
      volumes.push_back({++next, loops});
    }
  }

  std::string name;
  gmsh::model::getCurrent(name);
  gmsh::model::remove();
  gmsh::model::add(name);
  for (const EntityCopy& c : copies) gmsh::model::addDiscreteEntity(c.dim, c.tag, c.boundary);
  for (const EntityCopy& c : copies)
    if (!c.node_tags.empty()) gmsh::model::mesh::addNodes(c.dim, c.tag, c.node_tags, c.xyz);
  for (const EntityCopy& c : copies)
    for (std::size_t k = 0; k < c.types.size(); ++k)
      gmsh::model::mesh::addElementsByType(c.tag, c.types[k], c.element_tags[k],
                                           c.element_nodes[k]);
  std::vector<int> meshed;
  for (const auto& [tag, loops] : volumes) {
    std::vector<int> loop_tags;
    for (const auto& l : loops) loop_tags.push_back(gmsh::model::geo::addSurfaceLoop(l));
    gmsh::model::geo::addVolume(loop_tags, tag);
    meshed.push_back(tag);
  }
  gmsh::model::geo::synchronize();
  for (const GroupCopy& g : groups) {
    gmsh::model::addPhysicalGroup(g.dim, g.entities, g.tag);
    if (!g.name.empty()) gmsh::model::setPhysicalName(g.dim, g.tag, g.name);
  }
  generate_volumes(options);
  for (int v : meshed) {
    std::vector<int> types;
    gmsh::model::mesh::getElementTypes(types, 3, v);
    if (types.empty())
      throw InputError(what + ": Gmsh made no tetrahedra inside the surfaces of volume " +
                       std::to_string(v) + " (are they closed, without self-intersection?)");
  }
  std::sort(meshed.begin(), meshed.end());
  return meshed;
}

}  // namespace cvtmesh
