#include "core/pipeline/verify_mesh.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/face_key.h"
#include "core/mesh/find_surface_intersections.h"
#include "core/util/error.h"
#include "core/util/on_both.h"

namespace cvtmesh {
namespace {

template <class Mesh>
void check_valid(const Mesh& m) {
  const MeshCheck c = check_mesh(m);
  if (!c.ok) throw InvariantError("optimized mesh is invalid: " + c.problems.front());
}

std::string str(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Neumaier's compensated sum: the result is the exactly rounded sum of the terms up to a couple
// of ulps, whatever their number and order.
struct CompensatedSum {
  double sum = 0, c = 0;
  void add(double x) {
    const double t = sum + x;
    c += std::fabs(sum) >= std::fabs(x) ? (sum - t) + x : (x - t) + sum;
    sum = t;
  }
  double value() const { return sum + c; }
};

// Volumes (areas) of the regions are conserved to 1e-12 relative. Both sums are compensated, so
// what remains is the rounding of each simplex's volume: a few ulps of edge^3 per tet, |error|
// summed over the tets ~ 1e-15 * volume for reasonable shapes, and random in sign. The
// optimizers move interior vertices only and keep the boundary triangles, so the exact volumes
// are equal; 1e-12 leaves three orders of magnitude for slivers whose edge^3 is much larger than
// their volume.
constexpr double kVolumeTolerance = 1e-12;

// The boundary of the cells (tets, or triangles in 2D) of some regions: their facets (triangles,
// or edges) with no cell of those regions on the other side, as sorted vertex ids, sorted. K:
// vertices per cell; facet f is the one opposite vertex f, as in `adj` (used when it is built:
// O(#cells); otherwise all facets are sorted and those found once are kept).
template <int K>
std::vector<std::array<int, K - 1>> regions_boundary(const std::vector<int>& cells,
                                                     const std::vector<int>& cell_region,
                                                     const std::vector<int>& adj,
                                                     const std::vector<int>& regions) {
  auto inside = [&](std::size_t c) {
    return cells[K * c] >= 0 &&
           std::find(regions.begin(), regions.end(), cell_region[c]) != regions.end();
  };
  auto facet = [&](std::size_t c, int f) {
    std::array<int, K - 1> k;
    for (int i = 0, j = 0; i < K; ++i)
      if (i != f) k[j++] = cells[K * c + i];
    std::sort(k.begin(), k.end());
    return k;
  };
  std::vector<std::array<int, K - 1>> b;
  const bool with_adj = adj.size() == cells.size();
  for (std::size_t c = 0; c < cell_region.size(); ++c)
    if (inside(c))
      for (int f = 0; f < K; ++f)
        if (!with_adj || adj[K * c + f] < 0 ||
            !inside(static_cast<std::size_t>(adj[K * c + f] / K)))
          b.push_back(facet(c, f));
  std::sort(b.begin(), b.end());
  if (!with_adj) {  // an interior facet was listed twice: drop both
    std::vector<std::array<int, K - 1>> once;
    for (std::size_t i = 0; i < b.size();) {
      std::size_t j = i;
      while (j < b.size() && b[j] == b[i]) ++j;
      if (j - i == 1) once.push_back(b[i]);
      i = j;
    }
    b.swap(once);
  }
  return b;
}

std::string group_name(const PhysicalGroup& g) {
  return "physical group (dim " + std::to_string(g.dim) + ", tag " + std::to_string(g.tag) +
         (g.name.empty() ? "" : ", \"" + g.name + "\"") + ")";
}

// Every physical group of `before` is in `after` with the same name and entities, the model's
// entities keep their boundaries, and the points and lines are the same elements.
void check_model(const ModelInfo& mb, const ModelInfo& ma) {
  if (mb.groups.size() != ma.groups.size())
    throw InvariantError("physical groups changed (" + std::to_string(mb.groups.size()) + " -> " +
                         std::to_string(ma.groups.size()) + ")");
  auto sorted = [](std::vector<int> v) {
    std::sort(v.begin(), v.end());
    return v;
  };
  for (const PhysicalGroup& g : mb.groups) {
    const auto it = std::find_if(ma.groups.begin(), ma.groups.end(), [&](const PhysicalGroup& h) {
      return h.dim == g.dim && h.tag == g.tag;
    });
    if (it == ma.groups.end()) throw InvariantError(group_name(g) + " disappeared");
    if (it->name != g.name || sorted(it->entities) != sorted(g.entities))
      throw InvariantError(group_name(g) + " changed its name or entities");
  }
  // Boundaries as sets of entities: a periodic surface lists its seam curve twice (+c and -c) in
  // a model built from a .geo, once after a round trip through a .msh file (as for Gmsh's
  // optimizer baseline of `cvtmesh compare`); the curve is the same.
  auto entity_map = [](const ModelInfo& m) {
    std::map<std::pair<int, int>, std::set<int>> b;
    for (const ModelEntity& e : m.entities) {
      auto& s = b[{e.dim, e.tag}];
      for (int t : e.boundary) s.insert(std::abs(t));
    }
    return b;
  };
  if (entity_map(mb) != entity_map(ma))
    throw InvariantError("model entities or their boundaries changed");
  // Points and lines by entity and nodes (their element tags may be renumbered, as Gmsh does).
  auto blocks = [](const ModelInfo& m) {
    std::set<std::tuple<int, int, int, std::vector<int>>> s;
    for (const ElementBlock& b : m.extra) s.insert({b.dim, b.entity, b.gmsh_type, b.nodes});
    return s;
  };
  if (blocks(mb) != blocks(ma)) throw InvariantError("point or line elements changed");
}

// Each group of the mesh's dimension is bounded by the same facets before and after (the
// constrained facets themselves are compared by the caller; this also catches cells moved from
// one region to another across them). K: vertices per cell.
template <int K>
void check_group_boundaries(const std::vector<PhysicalGroup>& groups, int dim,
                            const std::vector<int>& cells_b, const std::vector<int>& region_b,
                            const std::vector<int>& adj_b, const std::vector<int>& cells_a,
                            const std::vector<int>& region_a, const std::vector<int>& adj_a) {
  for (const PhysicalGroup& g : groups)
    if (g.dim == dim && regions_boundary<K>(cells_b, region_b, adj_b, g.entities) !=
                            regions_boundary<K>(cells_a, region_a, adj_a, g.entities))
      throw InvariantError(group_name(g) + " is no longer bounded by the same " +
                           (K == 4 ? "triangles" : "edges"));
}

// Vertices added by the optimizer (ids from before's count on: the sliver repair's insertions,
// TetGen's Steiner points in a Lloyd rebuild) are interior vertices strictly inside one region:
// class dim 3 and, when in a tet, every tet around them of one region, their class's entity.
// They are on no constrained triangle: the triangles are compared by vertex ids, and check_mesh
// makes every boundary face of the tets a constrained triangle, so such a vertex is surrounded by
// its tets. A new vertex in no tet is tolerated (TetGen may leave a Steiner point in a hole of
// the domain, whose tets are dropped); it is in no element.
void check_new_vertices(const TetMesh& before, const TetMesh& after) {
  const int n0 = before.nb_vertices(), n1 = after.nb_vertices();
  if (n1 == n0) return;
  if (after.vclass.size() != static_cast<std::size_t>(n1))
    throw InvariantError("the vertex classification does not cover the new vertices");
  std::vector<int> region(static_cast<std::size_t>(n1 - n0), 0);
  std::vector<char> used(region.size(), 0);
  for (int t = 0; t < after.nb_tets(); ++t) {
    const int* v = &after.tets[4 * static_cast<std::size_t>(t)];
    if (v[0] < 0) continue;
    for (int k = 0; k < 4; ++k) {
      if (v[k] < n0) continue;
      const std::size_t i = static_cast<std::size_t>(v[k] - n0);
      if (used[i] && region[i] != after.tet_region[t])
        throw InvariantError("new vertex " + std::to_string(v[k]) +
                             " is on the interface of two regions");
      used[i] = 1;
      region[i] = after.tet_region[t];
    }
  }
  for (int v = n0; v < n1; ++v) {
    const std::size_t i = static_cast<std::size_t>(v - n0);
    if (after.vclass[v].dim != 3 || (used[i] && after.vclass[v].entity != region[i]))
      throw InvariantError("new vertex " + std::to_string(v) +
                           " is not classified as interior to its region");
  }
}

// Per surface tag: V - E + F of its triangles and its boundary edges (on one of its triangles),
// sorted.
std::map<int, std::pair<long, std::vector<std::array<int, 2>>>> surface_topology(const TetMesh& m) {
  std::map<int, std::map<std::array<int, 2>, int>> edges;
  std::map<int, std::set<int>> verts;
  std::map<int, long> faces;
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int s = m.tri_surface[f];
    ++faces[s];
    for (int k = 0; k < 3; ++k) {
      const int a = m.tris[3 * f + k], b = m.tris[3 * f + (k + 1) % 3];
      ++edges[s][{std::min(a, b), std::max(a, b)}];
      verts[s].insert(a);
    }
  }
  std::map<int, std::pair<long, std::vector<std::array<int, 2>>>> r;
  for (const auto& [s, e] : edges) {
    auto& t = r[s];
    t.first = static_cast<long>(verts[s].size()) - static_cast<long>(e.size()) + faces[s];
    for (const auto& [k, n] : e)
      if (n == 1) t.second.push_back(k);
  }
  return r;
}

// Per surface tag: how many of its triangles turn positively and negatively around the tet that
// holds them (of the lowest region tag, for an interface): orient3d(triangle, the tet's fourth
// vertex) > 0 or not. A positive tet fixes the side of each of its faces, so only rewriting a
// triangle's vertex order changes its sense.
std::map<int, std::array<long, 2>> surface_senses(const TetMesh& m) {
  std::unordered_map<FaceKey, int, FaceKeyHash> tri_of;
  tri_of.reserve(static_cast<std::size_t>(m.nb_tris()));
  for (int f = 0; f < m.nb_tris(); ++f)
    tri_of.emplace(face_key(m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]), f);
  std::vector<int> holder(static_cast<std::size_t>(m.nb_tris()), -1), apex(holder);
  const bool has_adj = m.adj.size() == m.tets.size();
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * static_cast<std::size_t>(t)];
    if (v[0] < 0) continue;
    for (int k = 0; k < 4; ++k) {
      const int o = has_adj ? m.adj[4 * static_cast<std::size_t>(t) + k] : -1;
      if (o >= 0 && m.tet_region[o / 4] == m.tet_region[t]) continue;
      const auto it = tri_of.find(face_key(v[(k + 1) % 4], v[(k + 2) % 4], v[(k + 3) % 4]));
      if (it == tri_of.end()) continue;
      int& h = holder[it->second];
      if (h < 0 || m.tet_region[t] < m.tet_region[h]) {
        h = t;
        apex[it->second] = v[k];
      }
    }
  }
  std::map<int, std::array<long, 2>> r;
  for (int f = 0; f < m.nb_tris(); ++f) {
    if (apex[f] < 0) continue;
    const int* w = &m.tris[3 * static_cast<std::size_t>(f)];
    ++r[m.tri_surface[f]]
       [orient3d(m.point(w[0]), m.point(w[1]), m.point(w[2]), m.point(apex[f])) > 0];
  }
  return r;
}

}  // namespace

std::vector<std::pair<int, double>> region_volumes(const TetMesh& m) {
  std::map<int, CompensatedSum> vol;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    vol[m.tet_region[t]].add(
        tet_volume(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])));
  }
  std::vector<std::pair<int, double>> r;
  for (const auto& [region, s] : vol) r.push_back({region, s.value()});
  return r;
}

void verify_optimized(const TetMesh& before, const TetMesh& after) {
  verify_optimized(before, after, VerifyOptions{});
}

void verify_optimized(const TetMesh& before, const TetMesh& after, const VerifyOptions& options) {
  check_valid(after);
  // Fixed vertices (on surfaces, curves, corners) keep their ids and coordinates.
  if (after.nb_vertices() < before.nb_vertices())
    throw InvariantError("optimized mesh lost vertices (" + std::to_string(before.nb_vertices()) +
                         " -> " + std::to_string(after.nb_vertices()) + ")");
  for (int v = 0; v < before.nb_vertices() && !options.boundary_moves; ++v)
    if (before.vclass[v].dim < 3)
      for (int d = 0; d < 3; ++d)
        if (before.point(v)[d] != after.point(v)[d])
          throw InvariantError("boundary vertex " + std::to_string(v) + " moved");
  // Same constrained triangles with the same surface tags.
  auto tri_set = [](const TetMesh& m) {
    std::multiset<std::tuple<int, int, int, int>> s;
    for (int f = 0; f < m.nb_tris(); ++f) {
      int a = m.tris[3 * f], b = m.tris[3 * f + 1], c = m.tris[3 * f + 2];
      int k[3] = {a, b, c};
      std::sort(k, k + 3);
      s.insert({k[0], k[1], k[2], m.tri_surface[f]});
    }
    return s;
  };
  if (!options.boundary_moves && tri_set(before) != tri_set(after))
    throw InvariantError("boundary or interface triangles changed");
  if (options.boundary_moves) {
    // Surface edge flips may change the triangles: each surface keeps its number of triangles
    // and its vertices (so, closed or not, its Euler characteristic: a flip keeps V, E and F).
    auto per_surface = [](const TetMesh& m) {
      std::map<int, std::pair<int, std::set<int>>> s;
      for (int f = 0; f < m.nb_tris(); ++f) {
        auto& e = s[m.tri_surface[f]];
        ++e.first;
        for (int k = 0; k < 3; ++k) e.second.insert(m.tris[3 * f + k]);
      }
      return s;
    };
    if (!options.boundary_collapses) {
      if (per_surface(before) != per_surface(after))
        throw InvariantError("a surface lost or gained triangles or vertices");
    } else {
      // The passes over the mesh before and after on two threads (on_both), both serial.
      const auto [sb, sa] = on_both(before, after, per_surface);
      const auto [tb, ta] = on_both(before, after, surface_topology);
      if (sb.size() != sa.size()) throw InvariantError("a surface disappeared or appeared");
      for (const auto& [tag, e] : sb) {
        const auto it = sa.find(tag);
        if (it == sa.end()) throw InvariantError("surface " + std::to_string(tag) + " disappeared");
        if (!std::includes(e.second.begin(), e.second.end(), it->second.second.begin(),
                           it->second.second.end()))
          throw InvariantError("surface " + std::to_string(tag) + " gained vertices");
        if (tb.at(tag) != ta.at(tag))
          throw InvariantError("surface " + std::to_string(tag) +
                               " changed its topology (Euler characteristic or boundary edges)");
      }
      // Only vertices of the boundary triangles may have left the tets.
      std::vector<char> on_tris(static_cast<std::size_t>(before.nb_vertices()), 0),
          used(static_cast<std::size_t>(after.nb_vertices()), 0);
      for (int v : before.tris) on_tris[v] = 1;
      for (int v : after.tets)
        if (v >= 0) used[v] = 1;
      for (int v : before.tets)
        if (v >= 0 && v < after.nb_vertices() && !used[v] && !on_tris[v])
          throw InvariantError("interior vertex " + std::to_string(v) + " is in no tet any more");
    }
  }
  check_new_vertices(before, after);
  // Region volumes conserved.
  const auto [vb, va] = on_both(before, after, region_volumes);
  if (vb.size() != va.size()) throw InvariantError("a region disappeared or appeared");
  for (std::size_t i = 0; i < vb.size(); ++i) {
    if (vb[i].first != va[i].first) throw InvariantError("region tags changed");
    // The volume of a region bounded by fixed triangles is fixed; the sums differ by rounding only.
    const double tol = options.volume_tolerance * std::fabs(vb[i].second);
    if (std::fabs(vb[i].second - va[i].second) > tol)
      throw InvariantError("volume of region " + std::to_string(vb[i].first) + " changed from " +
                           str(vb[i].second) + " to " + str(va[i].second));
  }
  check_model(before.model, after.model);
  if (!options.boundary_moves) {
    check_group_boundaries<4>(before.model.groups, 3, before.tets, before.tet_region, before.adj,
                              after.tets, after.tet_region, after.adj);
  } else {
    // Each volume group is bounded by as many triangles of each surface as before.
    for (const PhysicalGroup& g : before.model.groups) {
      if (g.dim != 3) continue;
      auto tags_of = [&](const TetMesh& m) {
        std::map<std::array<int, 3>, int> surface;
        for (int f = 0; f < m.nb_tris(); ++f) {
          std::array<int, 3> k = {m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]};
          std::sort(k.begin(), k.end());
          surface[k] = m.tri_surface[f];
        }
        std::map<int, int> count;  // surface tag (-1: not a constrained triangle) -> facets
        for (const auto& k : regions_boundary<4>(m.tets, m.tet_region, m.adj, g.entities)) {
          const auto it = surface.find(k);
          ++count[it == surface.end() ? -1 : it->second];
        }
        return count;
      };
      const auto [cb, ca] = on_both(before, after, tags_of);
      if (!options.boundary_collapses) {
        if (cb != ca)
          throw InvariantError(group_name(g) + " is no longer bounded by the same surfaces");
        continue;
      }
      // Collapses: the group loses as many triangles of each surface as the surface does.
      auto nb_tris = [](const TetMesh& m) {
        std::map<int, int> n;
        for (int f = 0; f < m.nb_tris(); ++f) ++n[m.tri_surface[f]];
        return n;
      };
      const auto nb = nb_tris(before), na = nb_tris(after);
      bool same = cb.size() == ca.size();
      for (const auto& [tag, n] : cb) {
        const auto it = ca.find(tag);
        const int lost = tag < 0 ? 0 : nb.at(tag) - (na.count(tag) ? na.at(tag) : 0);
        same &= it != ca.end() && n - it->second == lost;
      }
      if (!same) throw InvariantError(group_name(g) + " is no longer bounded by the same surfaces");
    }
  }
  // A surface whose triangles all turned one way around the volume (a Gmsh file's outward or
  // inward normals) still does, the same way: the surface flips rewrite triangles.
  {
    const auto [sb, sa] = on_both(before, after, surface_senses);
    for (const auto& [tag, n] : sb) {
      const auto it = sa.find(tag);
      if (it == sa.end() || (n[0] > 0 && n[1] > 0)) continue;
      const int way = n[1] > 0;
      if (it->second[1 - way] > 0)
        throw InvariantError(std::to_string(it->second[1 - way]) + " triangles of surface " +
                             std::to_string(tag) +
                             " were turned over (the input's all faced the same way)");
    }
  }
}

void verify_optimized(const TriMesh2& before, const TriMesh2& after) {
  check_valid(after);
  if (after.nb_vertices() < before.nb_vertices())
    throw InvariantError("optimized mesh lost vertices");
  for (int v = 0; v < before.nb_vertices(); ++v)
    if (before.vclass[v].dim < 2)
      for (int d = 0; d < 2; ++d)
        if (before.point(v)[d] != after.point(v)[d])
          throw InvariantError("boundary vertex " + std::to_string(v) + " moved");
  auto edge_set = [](const TriMesh2& m) {
    std::multiset<std::tuple<int, int, int>> s;
    for (int e = 0; e < m.nb_edges(); ++e)
      s.insert({std::min(m.edges[2 * e], m.edges[2 * e + 1]),
                std::max(m.edges[2 * e], m.edges[2 * e + 1]), m.edge_curve[e]});
    return s;
  };
  if (edge_set(before) != edge_set(after))
    throw InvariantError("boundary or interface edges changed");
  auto areas = [](const TriMesh2& m) {
    std::map<int, CompensatedSum> a;
    for (int t = 0; t < m.nb_tris(); ++t)
      if (m.tris[3 * t] >= 0)
        a[m.tri_region[t]].add(tri_area2d(m.point(m.tris[3 * t]), m.point(m.tris[3 * t + 1]),
                                          m.point(m.tris[3 * t + 2])));
    return a;
  };
  const auto ab = areas(before), aa = areas(after);
  if (ab.size() != aa.size()) throw InvariantError("a surface disappeared or appeared");
  for (const auto& [r, a] : ab) {
    const auto it = aa.find(r);
    if (it == aa.end()) throw InvariantError("surface " + std::to_string(r) + " disappeared");
    if (std::fabs(it->second.value() - a.value()) > kVolumeTolerance * std::fabs(a.value()))
      throw InvariantError("area of surface " + std::to_string(r) + " changed from " +
                           str(a.value()) + " to " + str(it->second.value()));
  }
  check_model(before.model, after.model);
  check_group_boundaries<3>(before.model.groups, 2, before.tris, before.tri_region, before.adj,
                            after.tris, after.tri_region, after.adj);
}

void verify_no_new_surface_crossing(const TetMesh& before, const TetMesh& after) {
  auto live_tris = [](const TetMesh& m) {
    std::vector<int> t;
    for (int f = 0; f < m.nb_tris(); ++f)
      if (m.tris[3 * f] >= 0) t.insert(t.end(), &m.tris[3 * f], &m.tris[3 * f] + 3);
    return t;
  };
  const auto crossing = find_surface_intersections(after.xyz, live_tris(after), 1);
  if (crossing.empty() || !find_surface_intersections(before.xyz, live_tris(before), 1).empty())
    return;
  throw InvariantError(
      "the free boundary made the boundary surface self-intersect (first: boundary triangles " +
      std::to_string(crossing[0][0]) + " and " + std::to_string(crossing[0][1]) + ")");
}

}  // namespace cvtmesh
