#include "core/io/gmsh_missing_facets.h"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "core/io/gmsh_model_elements.h"
#include "core/io/gmsh_partition_map.h"
#include "core/io/tag_index.h"
#include "core/mesh/face_buckets.h"

namespace cvtmesh {
namespace {

// A facet of the cells: its node tags as in its first cell (that cell's orientation), how many
// cells share it, the entities of the first two.
struct Facet {
  int count = 0;
  int cell_entity[2] = {0, 0};
  std::array<std::size_t, 3> nodes{};
};

// Dense ids for node tags, given in order of first appearance (tag_index.h: a table when the
// tags are dense, a hash map otherwise).
class DenseIds {
 public:
  DenseIds(std::size_t max_tag, std::size_t nb_refs) : index_(max_tag, nb_refs) {}
  std::uint32_t get_or_add(std::size_t tag) {
    int id = index_.find(tag);
    if (id < 0) index_.add(tag, id = static_cast<int>(next_++));
    return static_cast<std::uint32_t>(id);
  }
  std::uint32_t find(std::size_t tag) const {
    const int id = index_.find(tag);
    return id < 0 ? kNone : static_cast<std::uint32_t>(id);
  }
  std::uint32_t size() const { return next_; }
  static constexpr std::uint32_t kNone = 0xffffffffu;

 private:
  TagIndex index_;
  std::uint32_t next_ = 0;
};

}  // namespace

long add_missing_facets(int dim) {
  if (dim != 2 && dim != 3) return 0;
  // Linear cells and facets, and their order-2 kind (tet10 / tri6, tri6 / line3): the corners
  // come first. Missing facets are added linear (the order-2 reader takes their mid-edge nodes
  // from the cells' edges).
  const int cell_type = dim == 3 ? 4 : 2, facet_type = dim == 3 ? 2 : 1;
  const int cell_type2 = dim == 3 ? 11 : 9, facet_type2 = dim == 3 ? 9 : 8;
  const int npf = dim;  // nodes per facet
  const std::size_t npe = dim + 1;
  static const int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  static const int kEdge[3][2] = {{1, 2}, {2, 0}, {0, 1}};
  auto local = [&](std::size_t f, int k) { return dim == 3 ? kFace[f][k] : kEdge[f][k]; };

  // The cells, entity by entity; a facet is (cell, local face) numbered over all of them.
  struct Block {
    int entity = 0;
    std::vector<std::size_t> nodes;
  };
  std::vector<Block> blocks;
  std::vector<std::size_t> first_cell;  // per block, its first cell's global number
  std::size_t nb_cells = 0, max_node = 0;
  // A partitioned model's cells are its model volumes' (surfaces' in 2D), its ghost cells
  // skipped; facets between two parts of one volume are not interfaces (gmsh_partition_map.h).
  const GmshPartitionMap parts = read_gmsh_partition_map("the model");
  {
    gmsh::vectorpair cells_ents;
    gmsh::model::getEntities(cells_ents, dim);
    for (const GmshEntityElements& g : read_model_elements(cells_ents, parts)) {
      Block b;
      b.entity = g.tag;
      std::size_t nb = 0;
      for (int want : {cell_type, cell_type2})
        for (std::size_t k = 0; k < g.types.size(); ++k) {
          if (g.types[k] != want) continue;
          const std::vector<std::size_t>& nodes = g.nodes[k];
          const std::size_t nn = nodes.size() / std::max<std::size_t>(g.tags[k].size(), 1);
          for (std::size_t e = 0; e < g.tags[k].size(); ++e)
            b.nodes.insert(b.nodes.end(), &nodes[nn * e], &nodes[nn * e] + npe);
          nb += g.tags[k].size();
        }
      if (nb == 0) continue;
      for (std::size_t n : b.nodes) max_node = std::max(max_node, n);
      first_cell.push_back(nb_cells);
      nb_cells += nb;
      blocks.push_back(std::move(b));
    }
  }
  if (nb_cells == 0) return 0;
  auto cell_nodes = [&](std::size_t block, std::size_t cell) {
    return &blocks[block].nodes[npe * (cell - first_cell[block])];
  };
  // The dense ids of the cells' nodes (in the cells' order: deterministic), then the facets
  // (cell * npe + local face) bucketed by their sorted ids (face_buckets.h): equal facets are
  // adjacent, the first cell's first.
  DenseIds ids(max_node, nb_cells * npe);
  if (nb_cells * npe >= DenseIds::kNone)
    throw std::length_error("add_missing_facets: more than 2^32 facets");
  auto block_of = [&](std::size_t cell) {
    return static_cast<std::size_t>(std::upper_bound(first_cell.begin(), first_cell.end(), cell) -
                                    first_cell.begin() - 1);
  };
  std::vector<std::uint32_t> dense(nb_cells * npe);
  for (std::size_t bk = 0; bk < blocks.size(); ++bk)
    for (std::size_t e = 0; e < blocks[bk].nodes.size() / npe; ++e) {
      const std::size_t* c = &blocks[bk].nodes[npe * e];
      std::uint32_t* d = &dense[npe * (first_cell[bk] + e)];
      // Numbered facet by facet (the order the ids were given in before: the same output).
      for (std::size_t f = 0; f < npe; ++f)
        for (int k = 0; k < npf; ++k) d[local(f, k)] = ids.get_or_add(c[local(f, k)]);
    }
  FaceBuckets fb = bucket_faces(ids.size(), nb_cells * npe, [&](std::size_t i, std::uint32_t* k) {
    const std::uint32_t* c = &dense[i - i % npe];
    const std::size_t f = i % npe;
    k[0] = c[local(f, 0)];
    k[1] = c[local(f, 1)];
    k[2] = npf == 3 ? c[local(f, 2)] : 0;
    std::sort(k, k + npf);
    return true;
  });
  dense.clear();
  dense.shrink_to_fit();
  std::vector<FaceRecord>& sorted = fb.records;
  const std::vector<std::size_t>& start = fb.start;
  // Facets that are elements already (their first record marked); the largest element tag.
  std::vector<char> present(sorted.size(), 0);
  auto mark = [&](std::size_t a, std::size_t b, std::size_t c) {
    std::uint32_t key[3] = {ids.find(a), ids.find(b), ids.find(c)};
    for (std::uint32_t x : key)
      if (x == DenseIds::kNone) return;
    std::sort(key, key + 3);
    const FaceRecord probe{key[1], key[2], 0};
    auto first = sorted.begin() + start[key[0]], last = sorted.begin() + start[key[0] + 1];
    auto it = std::lower_bound(first, last, probe);
    if (it != last && same_face(*it, probe)) present[it - sorted.begin()] = 1;
  };
  // The faces of the kept 3D cells, by their corners (Gmsh's node order; order 2 has the
  // corners first): triangles as they are, quadrangles as the four triangles of three corners.
  auto mark_kept_cell_faces = [&](int type, const std::vector<std::size_t>& nodes,
                                  std::size_t count) {
    static const std::vector<std::vector<int>> kHex = {{0, 3, 2, 1}, {0, 1, 5, 4}, {0, 4, 7, 3},
                                                       {1, 2, 6, 5}, {2, 3, 7, 6}, {4, 5, 6, 7}};
    static const std::vector<std::vector<int>> kPrism = {
        {0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {0, 3, 5, 2}, {1, 2, 5, 4}};
    static const std::vector<std::vector<int>> kPyramid = {
        {0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    const std::vector<std::vector<int>>* faces = nullptr;
    if (type == 5 || type == 12 || type == 17) faces = &kHex;
    if (type == 6 || type == 13 || type == 18) faces = &kPrism;
    if (type == 7 || type == 14 || type == 19) faces = &kPyramid;
    if (!faces || count == 0) return;
    const std::size_t nn = nodes.size() / count;
    for (std::size_t e = 0; e < count; ++e) {
      const std::size_t* c = &nodes[nn * e];
      for (const auto& f : *faces) {
        if (f.size() == 3) {
          mark(c[f[0]], c[f[1]], c[f[2]]);
          continue;
        }
        for (int skip = 0; skip < 4; ++skip) {
          std::size_t t[3];
          for (int j = 0, n = 0; j < 4; ++j)
            if (j != skip) t[n++] = c[f[j]];
          mark(t[0], t[1], t[2]);
        }
      }
    }
  };
  std::size_t max_tag = 0;
  // A partitioned model: entity by entity, the facets of ghost and interface entities are not
  // the model's (Gmsh 4.8 may put a facet of a model surface that is also an interface between
  // parts on an interface entity of a volume).
  gmsh::vectorpair all = {{-1, -1}};
  if (parts.partitioned()) gmsh::model::getEntities(all);
  for (const auto& [d, t] : all) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> etags, enodes;
    gmsh::model::mesh::getElements(types, etags, enodes, d, t);
    const bool model = d < 0 || parts.element_owner(d, t).first >= 0;
    for (std::size_t k = 0; k < types.size(); ++k) {
      for (std::size_t tag : etags[k]) max_tag = std::max(max_tag, tag);
      // In 2D, a triangle edge on a quadrangle (a hybrid mesh: kept_quads.h) is no missing
      // line: the quadrangle is kept, and that edge constrained (constrain_kept_quad_edges.h).
      const bool quad = dim == 2 && types[k] == 3;
      // In 3D, a tet face on a kept cell (hybrid: a prism's or pyramid's triangle, or half of a
      // hexahedron's, prism's or pyramid's quadrangle) is no missing triangle either: the cell is
      // kept and that face constrained (constrain_kept_cell_faces.h), not written.
      if (model && dim == 3) mark_kept_cell_faces(types[k], enodes[k], etags[k].size());
      if (!model || (types[k] != facet_type && types[k] != facet_type2 && !quad)) continue;
      const std::size_t nn = enodes[k].size() / std::max<std::size_t>(etags[k].size(), 1);
      for (std::size_t e = 0; e < etags[k].size(); ++e)
        for (int side = 0; side < (quad ? 4 : 1); ++side) {
          std::uint32_t key[3] = {0, 0, 0};
          bool known = true;
          for (int j = 0; j < npf; ++j) {
            key[j] = ids.find(enodes[k][nn * e + (quad ? (side + j) % 4 : j)]);
            known &= key[j] != DenseIds::kNone;
          }
          if (!known) continue;
          std::sort(key, key + npf);
          const FaceRecord probe{key[1], npf == 3 ? key[2] : 0, 0};
          auto first = sorted.begin() + start[key[0]], last = sorted.begin() + start[key[0] + 1];
          auto it = std::lower_bound(first, last, probe);
          if (it != last && same_face(*it, probe)) present[it - sorted.begin()] = 1;
        }
    }
  }
  // The facets on the boundary (one cell) or between two entities, not elements yet.
  std::vector<Facet> facets;
  for (std::size_t a = 0; a < ids.size(); ++a) {
    for (std::size_t i = start[a]; i < start[a + 1];) {
      std::size_t j = i + 1;
      while (j < start[a + 1] && same_face(sorted[j], sorted[i])) ++j;
      if (!present[i]) {
        Facet fc;
        fc.count = static_cast<int>(j - i);
        for (std::size_t k = 0; k < 2 && i + k < j; ++k)
          fc.cell_entity[k] = blocks[block_of(sorted[i + k].id / npe)].entity;
        const std::size_t cell = sorted[i].id / npe, f = sorted[i].id % npe;
        const std::size_t* c = cell_nodes(block_of(cell), cell);
        for (int k = 0; k < npf; ++k) fc.nodes[k] = c[local(f, k)];
        const bool boundary = fc.count == 1;
        const bool interface = fc.count == 2 && fc.cell_entity[0] != fc.cell_entity[1];
        if (boundary || interface) facets.push_back(fc);
      }
      i = j;
    }
  }
  fb = FaceBuckets{};
  // Node classification on the lower-dimensional entities.
  std::unordered_map<std::size_t, std::pair<int, int>> where;
  for (int d = 0; d < dim; ++d) {
    gmsh::vectorpair ents;
    gmsh::model::getEntities(ents, d);
    for (const auto& [dd, t] : ents) {
      std::vector<std::size_t> tags;
      std::vector<double> xyz, par;
      gmsh::model::mesh::getNodes(tags, xyz, par, dd, t, false, false);
      const GmshDimTag owner = parts.node_owner(dd, t);
      if (owner.first >= dim) continue;  // an interface between parts inside a volume
      for (std::size_t n : tags) where[n] = owner;
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
  for (const Facet& fc : facets) {
    const bool interface = fc.count == 2;
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
