#include "core/io/gmsh_model.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "core/geometry/z_range.h"
#include "core/geometry/predicates.h"
#include "core/io/gmsh_model_elements.h"
#include "core/io/gmsh_partition_map.h"
#include "core/io/gmsh_repartition.h"
#include "core/io/gmsh_surface_mesh3.h"
#include "core/io/gmsh_session.h"
#include "core/mesh/reorient_tets.h"
#include "core/io/place_mid_edge_nodes.h"
#include "core/io/tag_index.h"
#include "core/mesh/keep_loose_triangles.h"
#include "core/mesh/constrain_kept_cell_faces.h"
#include "core/mesh/constrain_kept_quad_edges.h"
#include "core/mesh/keep_free_curve_lines.h"
#include "core/mesh/kept_quads.h"
#include "core/mesh/build_adjacency.h"
#include "core/mesh/check_surface_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

std::string type_name(int type) {
  std::string name;
  int dim = 0, order = 0, nn = 0, npn = 0;
  std::vector<double> lc;
  try {
    gmsh::model::mesh::getElementProperties(type, name, dim, order, nn, lc, npn);
  } catch (...) {
    name = "type " + std::to_string(type);
  }
  return name;
}

// Gmsh's order and node count of an element type (order 1, 0 nodes if Gmsh does not know it).
struct TypeProperties {
  int order = 1, nodes = 0;
};
TypeProperties type_properties(int type) {
  std::string name;
  int dim = 0, npn = 0;
  TypeProperties p;
  std::vector<double> lc;
  try {
    gmsh::model::mesh::getElementProperties(type, name, dim, p.order, p.nodes, lc, npn);
  } catch (...) {
  }
  return p;
}

int nodes_per_element_of(int type) {
  return type_properties(type).nodes;
}
int nodes_per_element(int type) {
  switch (type) {
    case 8:
      return 3;
    case 9:
      return 6;
    case 11:
      return 10;
    default:
      return nodes_per_element_of(type);
  }
}

int type_order(int type) {
  return type_properties(type).order;
}

// Order-2 simplices and their linear counterparts: line3 (8) -> line (1), tri6 (9) -> triangle
// (2), tet10 (11) -> tet (4); any other type is its own.
int linear_type(int type) {
  return type == 8 ? 1 : type == 9 ? 2 : type == 11 ? 4 : type;
}
int corners_of(int type) {
  switch (linear_type(type)) {
    case 1:
      return 2;
    case 2:
      return 3;
    case 4:
      return 4;
    default:
      return nodes_per_element_of(type);
  }
}
// Gmsh's order of the mid-edge nodes (after the corners): line3 (0,1); tri6 (0,1) (1,2) (2,0);
// tet10 (0,1) (1,2) (2,0) (3,0) (3,2) (3,1).
const std::vector<std::pair<int, int>>& mid_edge_table(int type) {
  static const std::vector<std::pair<int, int>> line3 = {{0, 1}}, tri6 = {{0, 1}, {1, 2}, {2, 0}},
                                                tet10 = {{0, 1}, {1, 2}, {2, 0},
                                                         {3, 0}, {3, 2}, {3, 1}},
                                                none;
  return type == 8 ? line3 : type == 9 ? tri6 : type == 11 ? tet10 : none;
}

// The order-2 hexahedra (12: 27 nodes, 17: 20), prisms (13: 18, 18: 15) and pyramids (14: 14,
// 19: 13) of a volume, quadrangles (10: 9, 16: 8) of a surface: kept verbatim in an order-2
// tet mesh.
bool is_order2_kept_type(int d, int type) {
  return (d == 3 &&
          (type == 12 || type == 13 || type == 14 || type == 17 || type == 18 || type == 19)) ||
         (d == 2 && (type == 10 || type == 16));
}

// For a high-order element: what to do instead.
std::string order_hint(int type) {
  if (type_order(type) <= 1) return "";
  return "; cvtmesh reads order-2 simplex meshes (tet10, tri6, line3); for another "
         "high-order mesh, optimize its order-1 mesh (gmsh -order 1, or Mesh.ElementOrder = 1) "
         "and raise the order afterwards (gmsh -order N)";
}

// A partitioned model's nodes (tags, 3 coordinates each) in the order of the unpartitioned file:
// by model entity (the order of `ents`), then by tag. Gmsh 4.8's partitioner adds a node on the
// partition entity of a model point that has none in the mesh (the centre of an arc, say): the
// nodes of partition entities that no element uses are dropped.
template <class Elements>
void order_partitioned_nodes(const GmshPartitionMap& parts, const gmsh::vectorpair& ents,
                             const Elements& elements, std::vector<std::size_t>& tags,
                             std::vector<double>& xyz) {
  std::map<GmshDimTag, std::size_t> position;
  for (std::size_t i = 0; i < ents.size(); ++i) position.emplace(ents[i], i);
  std::unordered_map<std::size_t, std::size_t> owner_position;
  std::unordered_set<std::size_t> unused;
  for (const auto& [d, t] : ents) {
    std::vector<std::size_t> nt;
    std::vector<double> c, p;
    gmsh::model::mesh::getNodes(nt, c, p, d, t, false, false);
    const auto it = position.find(parts.node_owner(d, t));
    const std::size_t pos = it == position.end() ? ents.size() : it->second;
    for (std::size_t n : nt) owner_position[n] = pos;
    if (!parts.is_model_entity(d, t)) unused.insert(nt.begin(), nt.end());
  }
  for (const auto& e : elements)
    for (const auto& nodes : e.enodes)
      for (std::size_t n : nodes) unused.erase(n);
  std::vector<std::size_t> order;
  order.reserve(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i)
    if (!unused.count(tags[i])) order.push_back(i);
  auto key = [&](std::size_t i) {
    const auto it = owner_position.find(tags[i]);
    return std::make_pair(it == owner_position.end() ? ents.size() : it->second, tags[i]);
  };
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::vector<std::size_t> t(order.size());
  std::vector<double> x(3 * order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    t[i] = tags[order[i]];
    std::copy_n(&xyz[3 * order[i]], 3, &x[3 * i]);
  }
  tags = std::move(t);
  xyz = std::move(x);
}

// The cells' parts by element tag (Partitioning::cell_tags, cell_parts).
void record_cell_parts(const std::vector<std::size_t>& tags, const std::vector<int>& parts,
                       Partitioning& p) {
  if (parts.size() != tags.size()) return;
  std::vector<std::size_t> order(tags.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return tags[a] < tags[b]; });
  p.cell_tags.resize(order.size());
  p.cell_parts.resize(order.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    p.cell_tags[i] = tags[order[i]];
    p.cell_parts[i] = parts[order[i]];
  }
}

std::string check_summary(const MeshCheck& c) {
  std::string s;
  for (std::size_t i = 0; i < c.problems.size() && i < 3; ++i) s += (i ? "; " : "") + c.problems[i];
  if (c.problems.size() > 3) s += "; ...";
  return s;
}

}  // namespace

MeshData mesh_from_gmsh(int dim, const std::string& what) {
  MeshData out;
  gmsh_checked("cannot read the mesh of " + what, [&] {
    ModelInfo info;
    gmsh::model::getCurrent(info.name);
    gmsh::vectorpair ents;
    gmsh::model::getEntities(ents);
    // A partitioned model is read as its model (gmsh_partition_map.h).
    const GmshPartitionMap parts = read_gmsh_partition_map(what);
    info.partitioning = parts.partitioning;
    // Highest dimension with elements.
    int max_dim = -1;
    for (const auto& [d, t] : ents) {
      std::vector<int> types;
      gmsh::model::mesh::getElementTypes(types, d, t);
      if (!types.empty()) max_dim = std::max(max_dim, d);
    }
    if (max_dim < 0) throw InputError(what + " has no mesh elements (empty mesh)");
    // Triangles on surfaces in space that bound no volume: a surface mesh in 3D, a TetMesh
    // without tets (gmsh_surface_mesh3.h); read so also when 3D is asked for (the GUI's 3D
    // panel on such a model).
    const bool surface3 = (dim < 0 || dim == 3) && max_dim == 2 && gmsh_surface_mesh_in_space();
    if (dim < 0) dim = surface3 ? 3 : max_dim;
    if (dim != 2 && dim != 3)
      throw InputError(what +
                       ": only 2D triangle and 3D tetrahedral meshes are supported (highest "
                       "element dimension is " +
                       std::to_string(max_dim) + ")");
    if (max_dim < dim && !surface3)
      throw InputError(what + " has no " + std::to_string(dim) + "D elements");
    out.dim = dim;

    for (const auto& [d, t] : ents) {
      if (!parts.is_model_entity(d, t)) continue;
      ModelEntity e;
      e.dim = d;
      e.tag = t;
      if (d > 0) {
        gmsh::vectorpair b;
        gmsh::model::getBoundary({{d, t}}, b, false, true, false);
        for (const auto& [bd, bt] : b) e.boundary.push_back(bt);
      }
      info.entities.push_back(e);
    }
    // Periodic links (entity and node correspondences), kept by node tag.
    for (const auto& [d, t] : ents) {
      if (!parts.is_model_entity(d, t)) continue;
      PeriodicLink l;
      l.dim = d;
      l.tag = t;
      try {
        gmsh::model::mesh::getPeriodicNodes(d, t, l.master, l.node_tags, l.master_node_tags,
                                            l.affine, false);
      } catch (...) {
        continue;
      }
      if (l.master != t && !l.node_tags.empty()) info.periodic.push_back(std::move(l));
    }
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    for (const auto& [d, t] : groups) {
      PhysicalGroup g;
      g.dim = d;
      g.tag = t;
      gmsh::model::getPhysicalName(d, t, g.name);
      gmsh::model::getEntitiesForPhysicalGroup(d, t, g.entities);
      info.groups.push_back(g);
    }
    parts.map_groups(info.groups);

    // Elements of every entity, read once.
    struct EntityElements {
      int d = 0, t = 0;
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> etags, enodes;
      std::vector<std::vector<int>> parts;  // a partitioned model's (gmsh_model_elements.h)
    };
    std::vector<EntityElements> elements;
    for (GmshEntityElements& g : read_model_elements(ents, parts))
      elements.push_back({g.dim, g.tag, std::move(g.types), std::move(g.tags), std::move(g.nodes),
                          std::move(g.parts)});
    // Order-2 simplices (line3, tri6, tet10): their corners make the mesh we optimize; their
    // mid-edge nodes are kept aside (info.high_order) and re-placed by the writers.
    bool order2 = false;
    for (const auto& e : elements)
      for (int type : e.types) order2 |= linear_type(type) != type;
    std::unordered_set<std::size_t> mid_nodes, corner_nodes;
    if (order2)
      for (const auto& e : elements)
        for (std::size_t k = 0; k < e.types.size(); ++k) {
          const int nn = nodes_per_element(e.types[k]), nc = corners_of(e.types[k]);
          const bool o2 = linear_type(e.types[k]) != e.types[k];
          for (std::size_t i = 0; i < e.enodes[k].size(); ++i)
            (o2 && static_cast<int>(i % nn) >= nc ? mid_nodes : corner_nodes)
                .insert(e.enodes[k][i]);
        }
    for (std::size_t n : corner_nodes) mid_nodes.erase(n);

    // Nodes, classified on the entity they belong to (not the mid-edge nodes of order 2).
    std::vector<std::size_t> all_tags, node_tags;
    std::vector<double> all_xyz, par;
    gmsh::model::mesh::getNodes(all_tags, all_xyz, par, -1, -1, false, false);
    if (parts.partitioned()) order_partitioned_nodes(parts, ents, elements, all_tags, all_xyz);
    std::unordered_map<std::size_t, std::size_t> all_index;  // tag -> position in all_tags
    if (order2) {
      all_index.reserve(all_tags.size() * 2);
      for (std::size_t i = 0; i < all_tags.size(); ++i) all_index.emplace(all_tags[i], i);
    }
    std::size_t max_tag = 0;
    for (std::size_t t : all_tags) max_tag = std::max(max_tag, t);
    TagIndex index(max_tag, all_tags.size());
    std::vector<double> xyz;
    std::vector<VertexClass> vclass;
    for (std::size_t i = 0; i < all_tags.size(); ++i) {
      for (int k = 0; k < 3; ++k)
        if (!std::isfinite(all_xyz[3 * i + k]))
          throw InputError(what + ": node " + std::to_string(all_tags[i]) +
                           " has a NaN or infinite coordinate");
      if (order2 && mid_nodes.count(all_tags[i])) continue;
      if (!index.add(all_tags[i], static_cast<int>(node_tags.size()))) {
        // The same node given again at the same place (a file that repeats its mesh: a view
        // appended with it, read_msh_format.h) is the same node; elsewhere, ambiguous.
        const int first = index.find(all_tags[i]);
        if (std::equal(&all_xyz[3 * i], &all_xyz[3 * i] + 3,
                       &xyz[3 * static_cast<std::size_t>(first)]))
          continue;
        throw InputError(what + ": node tag " + std::to_string(all_tags[i]) + " is duplicated");
      }
      node_tags.push_back(all_tags[i]);
      xyz.insert(xyz.end(), &all_xyz[3 * i], &all_xyz[3 * i] + 3);
      vclass.push_back({static_cast<std::int8_t>(dim), 0});
    }
    for (const auto& [d, t] : ents) {
      std::vector<std::size_t> tags;
      std::vector<double> c, p;
      gmsh::model::mesh::getNodes(tags, c, p, d, t, false, false);
      const GmshDimTag owner = parts.node_owner(d, t);
      for (std::size_t tag : tags) {
        const int v = index.find(tag);
        if (v < 0) continue;
        vclass[v].dim = static_cast<std::int8_t>(owner.first);
        vclass[v].entity = owner.second;
      }
    }
    auto vid = [&](std::size_t tag) {
      const int v = index.find(tag);
      if (v < 0)
        throw InputError(what + ": an element references node " + std::to_string(tag) +
                         ", which does not exist");
      return v;
    };
    // The input's mid-edge nodes, once per edge.
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> mid_of_edge;
    auto add_mid_nodes = [&](int type, const std::size_t* nd) {
      const auto& table = mid_edge_table(type);
      const int nc = corners_of(type);
      for (std::size_t k = 0; k < table.size(); ++k) {
        std::size_t a = nd[table[k].first], b = nd[table[k].second];
        if (a > b) std::swap(a, b);
        const std::size_t m = nd[nc + k];
        auto [it, fresh] = mid_of_edge.emplace(std::make_pair(a, b), m);
        if (!fresh) continue;
        auto pos = [&](std::size_t tag) {
          auto f = all_index.find(tag);
          if (f == all_index.end())
            throw InputError(what + ": an element references node " + std::to_string(tag) +
                             ", which does not exist");
          return &all_xyz[3 * f->second];
        };
        MidEdgeNodes& h = info.high_order;
        h.corner_tags.insert(h.corner_tags.end(), {a, b});
        h.corner_xyz.insert(h.corner_xyz.end(), pos(a), pos(a) + 3);
        h.corner_xyz.insert(h.corner_xyz.end(), pos(b), pos(b) + 3);
        h.tags.push_back(m);
        h.xyz.insert(h.xyz.end(), pos(m), pos(m) + 3);
      }
    };
    if (order2) info.high_order.order = 2;

    // Elements, entity by entity.
    std::vector<int> cells, cell_entity, facets, facet_entity;
    std::vector<std::size_t> cell_tags, facet_tags;
    std::vector<int> cell_parts;  // a partitioned model's
    for (const auto& el : elements) {
      const int d = el.d, t = el.t;
      for (std::size_t k = 0; k < el.types.size(); ++k) {
        // An order-2 simplex is read as its linear one (its corners come first).
        const int type = linear_type(el.types[k]);
        const auto& tg = el.etags[k];
        std::vector<std::size_t> corners;
        if (type != el.types[k]) {
          const int nn = nodes_per_element(el.types[k]), nc = corners_of(el.types[k]);
          for (std::size_t e = 0; e < tg.size(); ++e) {
            const std::size_t* en = &el.enodes[k][nn * e];
            corners.insert(corners.end(), en, en + nc);
            add_mid_nodes(el.types[k], en);
          }
        }
        const auto& nd = type != el.types[k] ? corners : el.enodes[k];
        // Hybrid meshes: hexahedra (5), prisms (6), pyramids (7) in a volume and quadrangles
        // (3) on a surface, in 3D and in 2D (kept_quads.h), are kept verbatim; optimize() fixes
        // their vertices (and smooths a 2D mesh's quadrangles).
        const bool kept_type =
            (d == 2 && type == 3) || (dim == 3 && d == 3 && (type == 5 || type == 6 || type == 7));
        // Their order-2 kinds in an order-2 3D mesh (hex27/20, prism18/15, pyramid14/13; quad9/8
        // on a surface) likewise, with all their nodes: every one a vertex (pinned), the ones on
        // edges they share with tet10s those tet10s' mid-edge nodes too.
        const bool kept_order2 = dim == 3 && order2 && is_order2_kept_type(d, type);
        // A block kept verbatim (ModelInfo::extra), all its nodes.
        auto keep_block = [&] {
          ElementBlock b;
          b.dim = d;
          b.entity = t;
          b.gmsh_type = type;
          b.tags = tg;
          for (std::size_t n : nd) b.nodes.push_back(vid(n));
          info.extra.push_back(std::move(b));
        };
        if (kept_order2) {
          keep_block();
          continue;
        }
        if (kept_type && order2)
          throw InputError(what + ": '" + type_name(type) + "' elements in an order-2 mesh " +
                           "(volume / surface " + std::to_string(t) +
                           "): order-2 hybrid meshes are not supported; optimize its order-1 "
                           "mesh (gmsh -order 1) and raise the order afterwards (gmsh -order 2)");
        if (kept_type || (d < dim - 1 && (type == 15 || type == 1))) {
          keep_block();
        } else if (d == dim) {
          const int want = dim == 3 ? 4 : 2;
          // Quadrangles of order 1 (3), 2 (10: 9 nodes, 16: 8 nodes) or higher.
          const bool quad = type_name(type).rfind("Quadrilateral", 0) == 0;
          if (type != want)
            throw InputError(
                what + ": unsupported element type '" + type_name(type) + "' in " +
                (dim == 3 ? "volume " : "surface ") + std::to_string(t) + " (cvtmesh optimizes " +
                (dim == 3 ? "tetrahedra" : "triangles") + " of order 1 or 2 only" +
                (quad ? "; mesh the surface without Recombine for triangles" : order_hint(type)) +
                ")");
          const int npe = dim + 1;
          for (std::size_t e = 0; e < tg.size(); ++e) {
            for (int j = 0; j < npe; ++j) cells.push_back(vid(nd[npe * e + j]));
            cell_entity.push_back(t);
            cell_tags.push_back(tg[e]);
          }
          if (!el.parts.empty())
            cell_parts.insert(cell_parts.end(), el.parts[k].begin(), el.parts[k].end());
        } else if (d == dim - 1) {
          const int want = dim == 3 ? 2 : 1;
          if (type != want)
            throw InputError(what + ": unsupported element type '" + type_name(type) + "' on " +
                             (dim == 3 ? "surface " : "curve ") + std::to_string(t) +
                             " (expected " + (dim == 3 ? "triangles" : "lines") +
                             " of order 1 or 2)" + order_hint(type));
          const int npe = dim;
          for (std::size_t e = 0; e < tg.size(); ++e) {
            for (int j = 0; j < npe; ++j) facets.push_back(vid(nd[npe * e + j]));
            facet_entity.push_back(t);
            facet_tags.push_back(tg[e]);
          }
        } else if (d < dim - 1) {
          throw InputError(what + ": unsupported element type '" + type_name(type) +
                           "' on entity (" + std::to_string(d) + "," + std::to_string(t) + ")" +
                           order_hint(type));
        } else {
          throw InputError(what + ": has " + std::to_string(d) + "D elements ('" + type_name(type) +
                           "') but is read as a " + std::to_string(dim) + "D mesh");
        }
      }
    }
    if (parts.partitioned()) {
      // A node of a boundary facet is on the boundary: an input whose classification came from
      // its elements (MSH 2.2, restored facets) may have put it on an interface between parts.
      for (std::size_t f = 0; f < facet_entity.size(); ++f)
        for (int k = 0; k < dim; ++k) {
          VertexClass& c = vclass[facets[dim * f + k]];
          if (c.dim == dim) c = {static_cast<std::int8_t>(dim - 1), facet_entity[f]};
        }
      record_cell_parts(cell_tags, cell_parts, info.partitioning);
    }
    bool kept_cells = false;
    for (const auto& b : info.extra) kept_cells |= b.dim == dim || (surface3 && b.dim == 2);
    if (cells.empty() && !kept_cells && !(surface3 && !facets.empty()))
      throw InputError(what + " has no " + std::string(dim == 3 ? "tetrahedra" : "triangles") +
                       " (empty mesh)");

    if (dim == 3) {
      TetMesh& m = out.tet;
      m.xyz = std::move(xyz);
      m.vclass = std::move(vclass);
      m.node_tags = std::move(node_tags);
      m.tets = std::move(cells);
      m.tet_region = std::move(cell_entity);
      m.tet_tags = std::move(cell_tags);
      m.tris = std::move(facets);
      m.tri_surface = std::move(facet_entity);
      m.tri_tags = std::move(facet_tags);
      m.model = std::move(info);
      if (surface3)
        m.model.read_notes.push_back(
            what + " holds triangles on surfaces in space that bound no volume: read as a " +
            "surface mesh in space");
      else
        keep_loose_triangles(m);
      // Tets in the other vertex order are turned positive (check_mesh then says whether they
      // form a mesh: a tangled one overlaps); flat ones are refused.
      const Reoriented ro = reorient_tets(m);
      if (ro.nb_flat)
        throw InputError(what + ": " + std::to_string(ro.nb_flat) +
                         " tetrahedra are flat (zero volume; first: element " +
                         std::to_string(m.tet_tags[ro.first_flat]) + ")");
      m.model.nb_reoriented = ro.nb_reoriented;
      if (ro.nb_reoriented)
        m.model.read_notes.push_back(reoriented_note(what, ro.nb_reoriented, m.nb_tets()));
      build_adjacency(m);
      constrain_kept_cell_faces(m);
      const MeshCheck c = check_mesh(m);
      if (!c.ok)
        throw InputError(what + ": invalid tetrahedral mesh: " +
                         (ro.nb_reoriented ? std::to_string(ro.nb_reoriented) +
                                                 " tetrahedra had negative volume and, turned "
                                                 "positive, do not form a mesh: "
                                           : std::string()) +
                         check_summary(c));
    } else {
      TriMesh2& m = out.tri;
      const std::size_t n = node_tags.size();
      // Planarity: every node of the 2D mesh at the same z (relative tolerance), an order-2
      // mesh's mid-edge nodes too.
      const ZRange zr = z_range(xyz);
      if (zr.planar && !info.high_order.xyz.empty()) {
        std::vector<double> all = xyz;
        all.insert(all.end(), info.high_order.xyz.begin(), info.high_order.xyz.end());
        if (!z_range(all).planar)
          throw InputError(what +
                           ": the mid-edge nodes of the order-2 triangles are not in the plane of "
                           "their corners (z = " +
                           std::to_string(zr.zmin) +
                           "); 2D optimization needs a mesh in a plane z = const");
      }
      const double zmin = zr.zmin, zmax = zr.zmax;
      // The surfaces that leave the plane of the first one, named in the message.
      std::string off_plane;
      if (!zr.planar) {
        std::map<int, std::vector<int>> by_surface;
        for (std::size_t e = 0; e < cell_entity.size(); ++e)
          for (int k = 0; k < 3; ++k) by_surface[cell_entity[e]].push_back(cells[3 * e + k]);
        double z0 = 0;
        bool first = true;
        int listed = 0;
        for (const auto& [srf, ids] : by_surface) {
          const ZRange r = z_range(xyz, &ids);
          if (first) z0 = r.zmin;
          first = false;
          std::vector<double> two = {0, 0, z0, 0, 0, r.zmin, 0, 0, r.zmax};
          if (!r.planar || !z_range(two).planar) {
            if (listed++ < 8) off_plane += (off_plane.empty() ? "" : ", ") + std::to_string(srf);
          }
        }
        if (listed > 8) off_plane += ", ...";
      }
      if (!zr.planar)
        throw InputError(what + ": the triangle mesh is not planar" +
                         (off_plane.empty()
                              ? ""
                              : " (surfaces " + off_plane +
                                    " are not in the plane z = const of the first surface)") +
                         " (z varies from " + std::to_string(zmin) + " to " + std::to_string(zmax) +
                         "); 2D optimization needs a mesh in a plane z = const");
      m.z0 = n ? zmin : 0;
      m.xy.resize(2 * n);
      for (std::size_t i = 0; i < n; ++i) {
        m.xy[2 * i] = xyz[3 * i];
        m.xy[2 * i + 1] = xyz[3 * i + 1];
      }
      m.vclass = std::move(vclass);
      m.node_tags = std::move(node_tags);
      m.tris = std::move(cells);
      m.tri_region = std::move(cell_entity);
      m.tri_tags = std::move(cell_tags);
      m.edges = std::move(facets);
      m.edge_curve = std::move(facet_entity);
      m.edge_tags = std::move(facet_tags);
      m.model = std::move(info);
      // Orientation per surface: clockwise surfaces are stored counter-clockwise.
      std::map<int, std::pair<long, long>> sign;  // surface -> (ccw, cw)
      for (int t = 0; t < m.nb_tris(); ++t) {
        const int* v = &m.tris[3 * t];
        const double o = orient2d(m.point(v[0]), m.point(v[1]), m.point(v[2]));
        if (o > 0)
          ++sign[m.tri_region[t]].first;
        else if (o < 0)
          ++sign[m.tri_region[t]].second;
        else
          throw InputError(what + ": triangle " + std::to_string(m.tri_tags[t]) +
                           " is flat (zero area)");
      }
      // A surface's turning sense is its triangles' majority (a tie: counter-clockwise);
      // triangles in the other sense (Gmsh's own triangulate returns either) are turned to it,
      // as tets given with negative volume are: check_mesh then says whether they form a mesh.
      long nb_turned = 0;
      for (const auto& [s, c] : sign) {
        if (c.second > c.first) m.cw_surfaces.push_back(s);
        nb_turned += std::min(c.first, c.second);
      }
      for (int t = 0; t < m.nb_tris(); ++t) {
        const int* v = &m.tris[3 * t];
        if (orient2d(m.point(v[0]), m.point(v[1]), m.point(v[2])) < 0)
          std::swap(m.tris[3 * t + 1], m.tris[3 * t + 2]);
      }
      m.model.nb_reoriented = nb_turned;
      if (nb_turned)
        m.model.read_notes.push_back(
            what + ": " + std::to_string(nb_turned) + " of " + std::to_string(m.nb_tris()) +
            " triangles turned the other way round than their surface's majority: turned to it");
      // 2D hybrid meshes and free curves: lines on no triangle kept verbatim, quadrangles'
      // surfaces oriented, their edges towards triangles constrained.
      keep_free_curve_lines(m);
      orient_quad_surfaces(m);
      build_adjacency2(m);
      constrain_kept_quad_edges(m);
      const MeshCheck c = check_mesh(m);
      if (!c.ok)
        throw InputError(what + ": invalid triangle mesh: " +
                         (nb_turned ? std::to_string(nb_turned) +
                                          " triangles were turned the other way round than their "
                                          "surface's majority and, turned to it, overlap their "
                                          "neighbours (do not form a mesh): "
                                    : std::string()) +
                         check_summary(c));
    }
  });
  return out;
}

void complete_model_info(MeshData& data) {
  ModelInfo& info = data.model();
  std::set<std::pair<int, int>> have;
  for (const auto& e : info.entities) have.insert({e.dim, e.tag});
  auto ensure = [&](int d, int t) {
    if (have.insert({d, t}).second) info.entities.push_back({d, t, {}});
  };
  if (data.dim == 3) {
    TetMesh& m = data.tet;
    for (int r : m.tet_region) ensure(3, r);
    for (int s : m.tri_surface)
      if (!is_kept_cell_interface(s)) ensure(2, s);
    if (m.vclass.size() != static_cast<std::size_t>(m.nb_vertices()))
      m.vclass.assign(m.nb_vertices(), {3, 0});
    for (int f = 0; f < m.nb_tris(); ++f)
      for (int k = 0; k < 3; ++k) {
        VertexClass& c = m.vclass[m.tris[3 * f + k]];
        if (c.entity == 0 || c.dim == 3) c = {2, m.tri_surface[f]};
      }
    for (int t = 0; t < m.nb_tets(); ++t)
      if (m.tets[4 * t] >= 0)
        for (int k = 0; k < 4; ++k) {
          VertexClass& c = m.vclass[m.tets[4 * t + k]];
          if (c.entity == 0) c = {3, m.tet_region[t]};
        }
    for (auto& c : m.vclass) {
      if (c.entity == 0) c = {3, m.tet_region.empty() ? 1 : m.tet_region[0]};
      ensure(c.dim, c.entity);
    }
  } else {
    TriMesh2& m = data.tri;
    for (int r : m.tri_region) ensure(2, r);
    for (int c : m.edge_curve)
      if (!is_kept_cell_interface(c)) ensure(1, c);
    if (m.vclass.size() != static_cast<std::size_t>(m.nb_vertices()))
      m.vclass.assign(m.nb_vertices(), {2, 0});
    for (int e = 0; e < m.nb_edges(); ++e)
      for (int k = 0; k < 2; ++k) {
        VertexClass& c = m.vclass[m.edges[2 * e + k]];
        if (is_kept_cell_interface(m.edge_curve[e])) continue;
        if (c.entity == 0 || c.dim == 2) c = {1, m.edge_curve[e]};
      }
    for (int t = 0; t < m.nb_tris(); ++t)
      if (m.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k) {
          VertexClass& c = m.vclass[m.tris[3 * t + k]];
          if (c.entity == 0) c = {2, m.tri_region[t]};
        }
    for (auto& c : m.vclass) {
      if (c.entity == 0) c = {2, m.tri_region.empty() ? 1 : m.tri_region[0]};
      ensure(c.dim, c.entity);
    }
  }
  for (const auto& b : info.extra) ensure(b.dim, b.entity);
  std::stable_sort(info.entities.begin(), info.entities.end(),
                   [](const ModelEntity& a, const ModelEntity& b) { return a.dim < b.dim; });
}

namespace {

// Node tags for every vertex: the original ones where known, fresh ones above the maximum (and
// above `floor`: tags taken by other nodes, e.g. an order-2 input's mid-edge nodes).
std::vector<std::size_t> node_tags_for(const std::vector<std::size_t>& original, int nv,
                                       std::size_t floor = 0) {
  std::vector<std::size_t> tags(nv, 0);
  std::size_t next = floor + 1;
  for (int i = 0; i < nv && i < static_cast<int>(original.size()); ++i)
    next = std::max(next, original[i] + 1);
  std::set<std::size_t> used;
  for (int i = 0; i < nv; ++i) {
    if (i < static_cast<int>(original.size()) && original[i] != 0 &&
        used.insert(original[i]).second)
      tags[i] = original[i];
    else
      tags[i] = next++;
  }
  return tags;
}

// An order-2 mesh's mid-edge nodes for the mesh being written: the placement made for these
// coordinates (place_mid_edge_nodes with the CAD, by the caller), else one made here (no CAD).
template <class Mesh>
MidEdgePlacement mid_edge_nodes_for(const Mesh& m) {
  const MidEdgePlacement& p = m.model.high_order.placed;
  if (!p.edges.empty() && p.fingerprint == mid_edge_fingerprint(m)) return p;
  return place_mid_edge_nodes(m);
}

struct ElementSet {
  std::vector<std::size_t> tags;  // one per live element
};

// Fills entities/nodes/elements of the current model. Returns the tags of the main simplices.
GmshWritten fill_current_model(const MeshData& data, bool create_entities) {
  GmshWritten w;
  const ModelInfo& info = data.model();
  const int dim = data.dim;
  if (create_entities) {
    for (const auto& e : info.entities) gmsh::model::addDiscreteEntity(e.dim, e.tag, e.boundary);
  }
  // Nodes.
  const int nv = dim == 3 ? data.tet.nb_vertices() : data.tri.nb_vertices();
  const auto& vclass = dim == 3 ? data.tet.vclass : data.tri.vclass;
  const bool order2 = info.high_order.order == 2;
  MidEdgePlacement mid;
  std::size_t floor = 0;
  if (order2) {
    mid = dim == 3 ? mid_edge_nodes_for(data.tet) : mid_edge_nodes_for(data.tri);
    for (std::size_t t : info.high_order.tags) floor = std::max(floor, t);
  }
  const auto ntags = node_tags_for(dim == 3 ? data.tet.node_tags : data.tri.node_tags, nv, floor);
  w.node_tags = ntags;
  // Mid-edge node tags: the input's where the edge is the input's, fresh ones above every other.
  // A mid-edge node that is a vertex too (a node of an order-2 kept cell, prism18 say, on an edge
  // it shares with tet10s: pinned, its edge's corners too) is that vertex, written once.
  std::vector<std::size_t> mid_tags(mid.tags.size());
  std::vector<char> mid_is_vertex(mid.tags.size(), 0);
  if (order2) {
    const std::set<std::size_t> vertex_tags(ntags.begin(), ntags.end());
    std::set<std::size_t> taken = vertex_tags;
    std::size_t next = floor + 1;
    for (std::size_t t : ntags) next = std::max(next, t + 1);
    for (std::size_t k = 0; k < mid.tags.size(); ++k) {
      mid_is_vertex[k] = mid.tags[k] && vertex_tags.count(mid.tags[k]);
      mid_tags[k] =
          mid_is_vertex[k] || (mid.tags[k] && taken.insert(mid.tags[k]).second) ? mid.tags[k] : 0;
    }
    for (std::size_t k = 0; k < mid.tags.size(); ++k)
      if (!mid_tags[k]) mid_tags[k] = next++;
  }
  // The mid-edge node of the edge (a, b) (order 2).
  auto mid_tag = [&](int a, int b) {
    if (a > b) std::swap(a, b);
    std::size_t lo = 0, hi = mid.tags.size();
    while (lo < hi) {
      const std::size_t k = (lo + hi) / 2;
      const int ka = mid.edges[2 * k], kb = mid.edges[2 * k + 1];
      if (ka < a || (ka == a && kb < b))
        lo = k + 1;
      else
        hi = k;
    }
    if (lo == mid.tags.size() || mid.edges[2 * lo] != a || mid.edges[2 * lo + 1] != b)
      throw InvariantError("order-2 output: no mid-edge node for the edge (" + std::to_string(a) +
                           ", " + std::to_string(b) + ")");
    return mid_tags[lo];
  };
  std::map<std::pair<int, int>, std::pair<std::vector<std::size_t>, std::vector<double>>>
      per_entity;
  for (int i = 0; i < nv; ++i) {
    auto& [tags, xyz] = per_entity[{vclass[i].dim, vclass[i].entity}];
    tags.push_back(ntags[i]);
    if (dim == 3) {
      const double* p = data.tet.point(i);
      xyz.insert(xyz.end(), p, p + 3);
    } else {
      const double* p = data.tri.point(i);
      xyz.insert(xyz.end(), {p[0], p[1], data.tri.z0});
    }
  }
  for (std::size_t k = 0; k < mid.tags.size(); ++k) {
    if (mid_is_vertex[k]) continue;
    auto& [tags, xyz] = per_entity[{mid.where[k].dim, mid.where[k].entity}];
    tags.push_back(mid_tags[k]);
    xyz.insert(xyz.end(), &mid.xyz[3 * k], &mid.xyz[3 * k] + 3);
  }
  for (const auto& [key, v] : per_entity)
    gmsh::model::mesh::addNodes(key.first, key.second, v.first, v.second);
  // Order 2: the Gmsh type and node list of a simplex given by its corners.
  auto elevate = [&](int type, const int* c, std::vector<std::size_t>& nd) {
    static const int kLine[1][2] = {{0, 1}};
    static const int kTri[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    static const int kTet[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
    const int(*table)[2] = type == 1 ? kLine : type == 2 ? kTri : kTet;
    const int n = type == 1 ? 1 : type == 2 ? 3 : 6;
    for (int k = 0; k < n; ++k) nd.push_back(mid_tag(c[table[k][0]], c[table[k][1]]));
    return type == 1 ? 8 : type == 2 ? 9 : 11;
  };
  auto elevates = [&](int type) { return order2 && (type == 1 || type == 2 || type == 4); };

  // Element tags: keep the original ones where they are unique, fresh ones otherwise.
  std::size_t next = 1;
  auto bump = [&](const std::vector<std::size_t>& t) {
    for (std::size_t x : t) next = std::max(next, x + 1);
  };
  for (const auto& b : info.extra) bump(b.tags);
  if (dim == 3) {
    bump(data.tet.tet_tags);
    bump(data.tet.tri_tags);
  } else {
    bump(data.tri.tri_tags);
    bump(data.tri.edge_tags);
  }
  std::set<std::size_t> used;
  auto tag_for = [&](const std::vector<std::size_t>& orig, int i) {
    if (i < static_cast<int>(orig.size()) && orig[i] != 0 && used.insert(orig[i]).second)
      return orig[i];
    return next++;
  };
  for (const auto& b : info.extra) {
    std::vector<std::size_t> tg, nd;
    for (std::size_t e = 0; e < b.tags.size(); ++e)
      tg.push_back(tag_for(b.tags, static_cast<int>(e)));
    if (elevates(b.gmsh_type)) {
      const int npe = b.gmsh_type == 1 ? 2 : b.gmsh_type == 2 ? 3 : 4;
      int type = b.gmsh_type;
      for (std::size_t e = 0; e < b.tags.size(); ++e) {
        const int* c = &b.nodes[npe * e];
        for (int j = 0; j < npe; ++j) nd.push_back(ntags[c[j]]);
        type = elevate(b.gmsh_type, c, nd);
      }
      gmsh::model::mesh::addElementsByType(b.entity, type, tg, nd);
      continue;
    }
    for (int n : b.nodes) nd.push_back(ntags[n]);
    gmsh::model::mesh::addElementsByType(b.entity, b.gmsh_type, tg, nd);
  }
  auto add_simplices = [&](const std::vector<int>& conn, int npe, const std::vector<int>& entity,
                           const std::vector<std::size_t>& orig, int type, bool main,
                           const std::vector<int>* cw) {
    std::map<int, std::pair<std::vector<std::size_t>, std::vector<std::size_t>>> blocks;
    const int n = static_cast<int>(conn.size()) / npe;
    std::vector<std::pair<int, std::size_t>> order;  // (element index, tag) for the main ones
    for (int e = 0; e < n; ++e) {
      // Dead elements, and the not-written interface with kept cells (hybrid meshes).
      if (conn[npe * e] < 0 || is_kept_cell_interface(entity[e])) continue;
      auto& [tg, nd] = blocks[entity[e]];
      const std::size_t tag = tag_for(orig, e);
      tg.push_back(tag);
      const bool flip = cw && std::binary_search(cw->begin(), cw->end(), entity[e]);
      int c[4];
      for (int j = 0; j < npe; ++j) {
        int jj = j;
        if (flip && j > 0) jj = npe - j;  // (0,1,2) -> (0,2,1)
        c[j] = conn[npe * e + jj];
        nd.push_back(ntags[c[j]]);
      }
      if (elevates(type)) elevate(type, c, nd);
      if (main) w.element_tags.push_back(tag);
    }
    const int written = !elevates(type) ? type : type == 1 ? 8 : type == 2 ? 9 : 11;
    for (const auto& [ent, b] : blocks)
      gmsh::model::mesh::addElementsByType(ent, written, b.first, b.second);
  };
  if (dim == 3) {
    // A surface mesh in space (no tets): its triangles are its elements (their tags are the
    // ones the quality views are keyed on).
    add_simplices(data.tet.tris, 3, data.tet.tri_surface, data.tet.tri_tags, 2,
                  is_surface_mesh(data.tet), nullptr);
    add_simplices(data.tet.tets, 4, data.tet.tet_region, data.tet.tet_tags, 4, true, nullptr);
  } else {
    add_simplices(data.tri.edges, 2, data.tri.edge_curve, data.tri.edge_tags, 1, false, nullptr);
    std::vector<int> cw = data.tri.cw_surfaces;
    std::sort(cw.begin(), cw.end());
    add_simplices(data.tri.tris, 3, data.tri.tri_region, data.tri.tri_tags, 2, true, &cw);
  }
  return w;
}

}  // namespace

GmshWritten mesh_to_gmsh(const MeshData& data, const std::string& model_name) {
  GmshWritten w;
  MeshData copy;
  const MeshData* d = &data;
  // Missing entities/classification are synthesized on a copy.
  bool complete = !data.model().entities.empty();
  if (complete) {
    std::set<std::pair<int, int>> have;
    for (const auto& e : data.model().entities) have.insert({e.dim, e.tag});
    const auto& vc = data.dim == 3 ? data.tet.vclass : data.tri.vclass;
    for (const auto& c : vc) complete &= c.entity != 0 && have.count({c.dim, c.entity}) > 0;
  }
  if (!complete) {
    copy = data;
    complete_model_info(copy);
    d = &copy;
  }
  gmsh_checked("cannot build the Gmsh model", [&] {
    gmsh::model::add(model_name);
    w = fill_current_model(*d, true);
    for (const auto& g : d->model().groups) {
      gmsh::model::addPhysicalGroup(g.dim, g.entities, g.tag);
      if (!g.name.empty()) gmsh::model::setPhysicalName(g.dim, g.tag, g.name);
    }
  });
  return w;
}

GmshWritten replace_gmsh_mesh(const MeshData& data) {
  GmshWritten w;
  gmsh_checked("cannot replace the mesh of the current Gmsh model", [&] {
    // A partitioned model: its mesh goes back to the model entities, is replaced, and is
    // partitioned again (gmsh_repartition.h).
    const Partitioning& parts = data.model().partitioning;
    if (parts.nb_parts > 0) gmsh::model::mesh::unpartition();
    gmsh::model::mesh::clear();
    w = fill_current_model(data, false);
    if (parts.nb_parts > 0) repartition_gmsh_model(parts, data.dim);
  });
  return w;
}

std::vector<int> add_element_views(const std::vector<ElementField>& fields,
                                   const std::vector<std::size_t>& element_tags) {
  std::vector<int> views;
  gmsh_checked("cannot add quality views", [&] {
    std::string model;
    gmsh::model::getCurrent(model);
    for (const auto& f : fields) {
      const int v = gmsh::view::add(f.name);
      std::vector<std::vector<double>> data(f.values.size());
      for (std::size_t i = 0; i < f.values.size(); ++i) data[i] = {f.values[i]};
      gmsh::view::addModelData(v, 0, model, "ElementData", element_tags, data);
      views.push_back(v);
    }
  });
  return views;
}

}  // namespace cvtmesh
