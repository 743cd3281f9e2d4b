#include "core/io/select_msh_elements.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <tuple>
#include <utility>

#include "core/mesh/constrain_kept_cell_faces.h"

namespace cvtmesh {
namespace {

using Key = std::array<int, 3>;  // (dim, entity, Gmsh element type)

}  // namespace

MshSelection select_msh_elements(const MeshData& data, bool save_all) {
  MshSelection s;
  s.data = data;
  MeshData& d = s.data;
  ModelInfo& info = d.model();
  std::set<std::pair<int, int>> grouped;
  bool group_of_dim = false;
  for (const auto& g : info.groups) {
    group_of_dim |= g.dim == d.dim;
    for (int e : g.entities) grouped.insert({g.dim, e});
  }
  const bool by_file = !save_all && info.origin == ElementOrigin::kMeshFile;
  const bool by_groups = !save_all && info.origin == ElementOrigin::kModel && !grouped.empty();
  auto keep = [&](int dim, int entity, int type) {
    if (by_file)
      return std::binary_search(info.file_blocks.begin(), info.file_blocks.end(),
                                Key{dim, entity, type});
    if (by_groups) {
      // A model whose groups leave out every cell of the mesh dimension keeps its cells (Gmsh
      // would write a mesh without them, which no tool, ours included, could use).
      if (dim == d.dim && !group_of_dim) return true;
      return grouped.count({dim, entity}) > 0;
    }
    return true;
  };
  auto note = [&](int dim, int entity) {
    if (!info.groups.empty() && !grouped.count({dim, entity})) s.outside_groups = true;
  };
  // Facets not selected are removed from the copy (tags follow when present).
  auto select_facets = [&](std::vector<int>& conn, int npf, std::vector<int>& entity,
                           std::vector<std::size_t>& tags, int type) {
    std::size_t kept = 0;
    for (std::size_t f = 0; f < entity.size(); ++f) {
      const bool hidden = conn[npf * f] < 0 || is_kept_cell_interface(entity[f]);
      if (!hidden && !keep(d.dim - 1, entity[f], type)) continue;
      if (!hidden) note(d.dim - 1, entity[f]);
      for (int k = 0; k < npf; ++k) conn[npf * kept + k] = conn[npf * f + k];
      entity[kept] = entity[f];
      if (f < tags.size()) tags[kept] = tags[f];
      ++kept;
    }
    conn.resize(npf * kept);
    entity.resize(kept);
    if (tags.size() > kept) tags.resize(kept);
  };
  auto select_cells = [&](std::vector<int>& conn, int npe, const std::vector<int>& entity,
                          int type) {
    long live = 0;
    s.field_index.assign(entity.size(), -1);
    for (std::size_t c = 0; c < entity.size(); ++c) {
      if (conn[npe * c] < 0) continue;
      const long index = live++;
      if (!keep(d.dim, entity[c], type)) {
        conn[npe * c] = -1;
        continue;
      }
      note(d.dim, entity[c]);
      s.field_index[c] = index;
    }
  };
  if (d.dim == 3) {
    select_facets(d.tet.tris, 3, d.tet.tri_surface, d.tet.tri_tags, 2);
    select_cells(d.tet.tets, 4, d.tet.tet_region, 4);
  } else {
    select_facets(d.tri.edges, 2, d.tri.edge_curve, d.tri.edge_tags, 1);
    select_cells(d.tri.tris, 3, d.tri.tri_region, 2);
  }
  auto& extra = info.extra;
  extra.erase(
      std::remove_if(extra.begin(), extra.end(),
                     [&](const ElementBlock& b) { return !keep(b.dim, b.entity, b.gmsh_type); }),
      extra.end());
  for (const auto& b : extra) note(b.dim, b.entity);
  s.save_all = info.groups.empty() || s.outside_groups;
  return s;
}

std::size_t number_in_file_order(MeshData& data) {
  // (key, which array, index): 0..k-1 the extra blocks, k the facets, k+1 the cells.
  std::vector<std::tuple<Key, std::size_t, std::size_t>> items;
  auto& extra = data.model().extra;
  const std::size_t facets = extra.size(), cells = extra.size() + 1;
  for (std::size_t b = 0; b < extra.size(); ++b)
    for (std::size_t e = 0; e < extra[b].tags.size(); ++e)
      items.push_back({{extra[b].dim, extra[b].entity, extra[b].gmsh_type}, b, e});
  const int dim = data.dim;
  const std::vector<int>& fconn = dim == 3 ? data.tet.tris : data.tri.edges;
  const std::vector<int>& fent = dim == 3 ? data.tet.tri_surface : data.tri.edge_curve;
  const std::vector<int>& cconn = dim == 3 ? data.tet.tets : data.tri.tris;
  const std::vector<int>& cent = dim == 3 ? data.tet.tet_region : data.tri.tri_region;
  const int npf = dim, npe = dim + 1;
  for (std::size_t f = 0; f < fent.size(); ++f)
    if (fconn[npf * f] >= 0 && !is_kept_cell_interface(fent[f]))
      items.push_back({{dim - 1, fent[f], dim == 3 ? 2 : 1}, facets, f});
  for (std::size_t c = 0; c < cent.size(); ++c)
    if (cconn[npe * c] >= 0) items.push_back({{dim, cent[c], dim == 3 ? 4 : 2}, cells, c});
  std::stable_sort(items.begin(), items.end(),
                   [](const auto& a, const auto& b) { return std::get<0>(a) < std::get<0>(b); });
  std::vector<std::size_t>& ftags = dim == 3 ? data.tet.tri_tags : data.tri.edge_tags;
  std::vector<std::size_t>& ctags = dim == 3 ? data.tet.tet_tags : data.tri.tri_tags;
  // Tags already 1..N in file order (a mesh Gmsh numbered, not edited) are kept.
  auto tag_of = [&](std::size_t which, std::size_t i) -> std::size_t {
    const std::vector<std::size_t>& t = which == facets  ? ftags
                                        : which == cells ? ctags
                                                         : extra[which].tags;
    return i < t.size() ? t[i] : 0;
  };
  bool in_order = true;
  for (std::size_t k = 0; k < items.size() && in_order; ++k)
    in_order = tag_of(std::get<1>(items[k]), std::get<2>(items[k])) == k + 1;
  if (in_order) return items.size();
  ftags.assign(fent.size(), 0);
  ctags.assign(cent.size(), 0);
  std::size_t next = 0;
  for (const auto& [key, which, i] : items) {
    ++next;
    if (which == facets)
      ftags[i] = next;
    else if (which == cells)
      ctags[i] = next;
    else
      extra[which].tags[i] = next;
  }
  return next;
}

bool number_nodes_in_file_order(MeshData& data) {
  const bool three = data.dim == 3;
  const std::vector<VertexClass>& vc = three ? data.tet.vclass : data.tri.vclass;
  std::vector<std::size_t>& tags = three ? data.tet.node_tags : data.tri.node_tags;
  const std::size_t nv = three ? data.tet.xyz.size() / 3 : data.tri.xy.size() / 2;
  std::vector<std::size_t> order(nv);
  for (std::size_t v = 0; v < nv; ++v) order[v] = v;
  auto key = [&](std::size_t v) {
    return v < vc.size() ? std::make_pair(static_cast<int>(vc[v].dim), vc[v].entity)
                         : std::make_pair(three ? 3 : 2, 0);
  };
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  bool in_order = tags.size() == nv;
  for (std::size_t k = 0; k < nv && in_order; ++k) in_order = tags[order[k]] == k + 1;
  if (in_order) return true;
  if (data.model().high_order.order == 2 || !data.model().periodic.empty()) return false;
  tags.assign(nv, 0);
  for (std::size_t k = 0; k < nv; ++k) tags[order[k]] = k + 1;
  return true;
}

std::vector<ElementField> fields_on_all_elements(const MshSelection& numbered,
                                                 const std::vector<ElementField>& fields,
                                                 std::size_t nb_elements) {
  const MeshData& d = numbered.data;
  const std::vector<std::size_t>& ctags = d.dim == 3 ? d.tet.tet_tags : d.tri.tri_tags;
  std::vector<ElementField> out;
  for (const ElementField& f : fields) {
    ElementField g{f.name,
                   std::vector<double>(nb_elements, std::numeric_limits<double>::quiet_NaN())};
    for (std::size_t c = 0; c < numbered.field_index.size() && c < ctags.size(); ++c) {
      const long i = numbered.field_index[c];
      if (i >= 0 && ctags[c] > 0 && static_cast<std::size_t>(i) < f.values.size())
        g.values[ctags[c] - 1] = f.values[i];
    }
    out.push_back(std::move(g));
  }
  return out;
}

}  // namespace cvtmesh
