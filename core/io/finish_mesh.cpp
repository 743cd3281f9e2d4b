#include "core/io/finish_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/mesh/build_adjacency.h"
#include "core/mesh/reorient_tets.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/face_key.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

std::string s(long v) {
  return std::to_string(v);
}

std::string check_summary(const MeshCheck& c) {
  std::string r;
  for (std::size_t i = 0; i < c.problems.size() && i < 3; ++i) r += (i ? "; " : "") + c.problems[i];
  if (c.problems.size() > 3) r += "; ...";
  return r;
}

void add_unique(std::vector<int>& v, int x) {
  if (std::find(v.begin(), v.end(), x) == v.end()) v.push_back(x);
}

// Maps every distinct tag <= 0 to a fresh positive tag above the largest one.
void positive_tags(std::vector<int>& tags) {
  int next = 1;
  for (int t : tags) next = std::max(next, t + 1);
  std::map<int, int> fresh;
  for (int& t : tags)
    if (t <= 0) {
      auto it = fresh.find(t);
      if (it == fresh.end()) it = fresh.emplace(t, next++).first;
      t = it->second;
    }
}

// Fresh facet tags above the given ones: the first for boundary facets, the next for interfaces.
struct FreshTags {
  int boundary = 1, interface = 2;
  explicit FreshTags(const std::vector<int>& tags) {
    for (int t : tags) boundary = std::max(boundary, t + 1);
    interface = boundary + 1;
  }
  int for_boundary() const { return boundary; }
  int for_interface() const { return interface; }
};

// Keeps the vertices some element uses; returns the old -> new map (-1 for dropped).
std::vector<int> used_vertices(const std::vector<int>& cells, int nv) {
  std::vector<int> map(nv, -1);
  for (int v : cells) map[v] = 0;
  int k = 0;
  for (int& m : map)
    if (m == 0) m = k++;
  return map;
}

template <class T>
void compact(std::vector<T>& values, const std::vector<int>& map, int stride) {
  if (values.size() != map.size() * stride) {
    values.clear();
    return;
  }
  std::vector<T> out;
  for (std::size_t i = 0; i < map.size(); ++i)
    if (map[i] >= 0)
      for (int k = 0; k < stride; ++k) out.push_back(values[stride * i + k]);
  values = std::move(out);
}

void check_ids(const std::vector<int>& ids, int per, int nv, const std::string& what,
               const std::string& kind) {
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (ids[i] < 0 || ids[i] >= nv)
      throw InputError(what + ": " + kind + " " + s(i / per + 1) + " refers to vertex " +
                       s(ids[i] + 1) + ", which does not exist (" + s(nv) + " vertices)");
  for (std::size_t e = 0; e + per <= ids.size(); e += per)
    for (int a = 0; a < per; ++a)
      for (int b = a + 1; b < per; ++b)
        if (ids[e + a] == ids[e + b])
          throw InputError(what + ": " + kind + " " + s(e / per + 1) + " uses vertex " +
                           s(ids[e + a] + 1) + " twice");
}

// ---------------------------------------------------------------------------------------------
// 3D

void classify3(TetMesh& m, const std::unordered_map<FaceKey, int, FaceKeyHash>& face_slot) {
  const int nv = m.nb_vertices();
  ModelInfo& info = m.model;
  // Feature edges: edges of the constrained triangles where two or more surfaces meet.
  std::unordered_map<EdgeKey, std::vector<int>, EdgeKeyHash> edge_surfaces;
  std::vector<EdgeKey> edge_order;
  for (int f = 0; f < m.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      const EdgeKey e = edge_key(m.tris[3 * f + k], m.tris[3 * f + (k + 1) % 3]);
      auto [it, fresh] = edge_surfaces.try_emplace(e);
      if (fresh) edge_order.push_back(e);
      add_unique(it->second, m.tri_surface[f]);
    }
  std::map<std::vector<int>, int> curve_of;  // sorted surface set -> curve tag
  std::vector<std::vector<int>> curve_surfaces;
  std::vector<std::vector<std::pair<int, int>>> vcurves(nv);  // (curve, degree)
  std::vector<std::vector<int>> curve_nodes;
  for (const EdgeKey& e : edge_order) {
    std::vector<int> key = edge_surfaces[e];
    if (key.size() < 2) continue;
    std::sort(key.begin(), key.end());
    auto it = curve_of.find(key);
    if (it == curve_of.end()) {
      it = curve_of.emplace(key, static_cast<int>(curve_of.size()) + 1).first;
      curve_surfaces.push_back(key);
      curve_nodes.emplace_back();
    }
    const int c = it->second;
    curve_nodes[c - 1].insert(curve_nodes[c - 1].end(), {e[0], e[1]});
    for (int v : e) {
      auto& vc = vcurves[v];
      auto j = std::find_if(vc.begin(), vc.end(), [&](const auto& p) { return p.first == c; });
      if (j == vc.end())
        vc.push_back({c, 1});
      else
        ++j->second;
    }
  }
  std::vector<int> vsurface(nv, 0), vregion(nv, 0);
  for (int f = 0; f < m.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      int& vs = vsurface[m.tris[3 * f + k]];
      if (vs == 0 || m.tri_surface[f] < vs) vs = m.tri_surface[f];
    }
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int k = 0; k < 4; ++k)
      if (vregion[m.tets[4 * t + k]] == 0) vregion[m.tets[4 * t + k]] = m.tet_region[t];

  m.vclass.assign(nv, VertexClass{});
  std::vector<std::vector<int>> curve_corners(curve_surfaces.size());
  int nb_points = 0;
  for (int v = 0; v < nv; ++v) {
    const auto& vc = vcurves[v];
    if (vc.size() >= 2 || (vc.size() == 1 && vc[0].second != 2)) {
      m.vclass[v] = {0, ++nb_points};
      for (const auto& [c, deg] : vc) curve_corners[c - 1].push_back(nb_points);
      info.entities.push_back({0, nb_points, {}});
      info.extra.push_back({0, nb_points, 15, {0}, {v}});
    } else if (vc.size() == 1) {
      m.vclass[v] = {1, vc[0].first};
    } else if (vsurface[v]) {
      m.vclass[v] = {2, vsurface[v]};
    } else {
      m.vclass[v] = {3, vregion[v]};
    }
  }
  for (std::size_t c = 0; c < curve_surfaces.size(); ++c) {
    const int tag = static_cast<int>(c) + 1;
    info.entities.push_back({1, tag, curve_corners[c]});
    info.extra.push_back(
        {1, tag, 1, std::vector<std::size_t>(curve_nodes[c].size() / 2, 0), curve_nodes[c]});
  }
  std::map<int, std::vector<int>> surface_curves, region_surfaces;
  for (int f = 0; f < m.nb_tris(); ++f) surface_curves[m.tri_surface[f]];
  for (std::size_t c = 0; c < curve_surfaces.size(); ++c)
    for (int srf : curve_surfaces[c]) surface_curves[srf].push_back(static_cast<int>(c) + 1);
  for (int r : m.tet_region) region_surfaces[r];
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int slot = face_slot.at(face_key(m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]));
    add_unique(region_surfaces[m.tet_region[slot / 4]], m.tri_surface[f]);
    if (m.adj[slot] >= 0)
      add_unique(region_surfaces[m.tet_region[m.adj[slot] / 4]], m.tri_surface[f]);
  }
  for (auto& [srf, curves] : surface_curves) info.entities.push_back({2, srf, curves});
  for (auto& [r, surfaces] : region_surfaces) {
    std::sort(surfaces.begin(), surfaces.end());
    info.entities.push_back({3, r, surfaces});
  }
}

void finish3(TetMesh& m, ModelInfo& info, const std::string& what) {
  if (m.xyz.size() % 3 != 0) throw InvariantError("finish_mesh: xyz is not #V by 3");
  for (std::size_t i = 0; i < m.xyz.size(); ++i)
    if (!std::isfinite(m.xyz[i]))
      throw InputError(what + ": vertex " + s(i / 3 + 1) + " has a NaN or infinite coordinate");
  if (m.tets.empty()) throw InputError(what + " has no tetrahedra (empty mesh)");
  const int nt = m.nb_tets();
  if (static_cast<int>(m.tet_region.size()) != nt) m.tet_region.assign(nt, 1);
  if (m.tri_surface.size() != m.tris.size() / 3) m.tri_surface.assign(m.tris.size() / 3, 0);
  check_ids(m.tets, 4, m.nb_vertices(), what, "tetrahedron");
  check_ids(m.tris, 3, m.nb_vertices(), what, "triangle");

  // Tets in the other vertex order are turned positive (whether they then form a mesh, the
  // overlap check below says); flat ones are refused.
  const Reoriented ro = reorient_tets(m);
  if (ro.nb_flat)
    throw InputError(what + ": " + s(ro.nb_flat) +
                     " tetrahedra are flat (zero volume; first: tetrahedron " +
                     s(ro.first_flat + 1) + ")");
  m.model.nb_reoriented = ro.nb_reoriented;
  if (ro.nb_reoriented) m.model.read_notes.push_back(reoriented_note(what, ro.nb_reoriented, nt));

  // Drop unused vertices.
  const std::vector<int> map = used_vertices(m.tets, m.nb_vertices());
  for (int& v : m.tets) v = map[v];
  for (std::size_t i = 0; i < m.tris.size(); ++i) {
    const int v = map[m.tris[i]];
    if (v < 0)
      throw InputError(what + ": triangle " + s(i / 3 + 1) + " is not a face of any tetrahedron");
    m.tris[i] = v;
  }
  compact(m.xyz, map, 3);
  compact(m.node_tags, map, 1);
  compact(m.vclass, map, 1);

  positive_tags(m.tet_region);
  try {
    build_adjacency(m);
  } catch (const InputError& e) {
    throw InputError(what + ": " + e.what());
  }
  std::unordered_map<FaceKey, int, FaceKeyHash> face_slot;
  face_slot.reserve(4 * static_cast<std::size_t>(nt));
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tets[4 * t];
    for (int f = 0; f < 4; ++f) {
      const int* fv = kTetFace[f];
      face_slot.emplace(face_key(tv[fv[0]], tv[fv[1]], tv[fv[2]]), 4 * t + f);
      const int o = m.adj[4 * t + f];
      if (o < 0 || o < 4 * t) continue;
      // Neighbours must lie on opposite sides of their common face.
      const int d2 = m.tets[o];  // the vertex of the neighbour opposite the face
      if (orient3d(m.point(tv[fv[0]]), m.point(tv[fv[1]]), m.point(tv[fv[2]]), m.point(d2)) <= 0)
        throw InputError(what + ": tetrahedra " + s(t + 1) + " and " + s(o / 4 + 1) +
                         " overlap (duplicated or folded elements)");
    }
  }

  // Constrained triangles: validate, drop duplicates and unmarked interior ones, add the missing
  // boundary and interface triangles.
  FreshTags fresh(m.tri_surface);
  std::vector<int> tris, surf;
  std::vector<std::size_t> tags;
  std::unordered_map<FaceKey, int, FaceKeyHash> have;
  const bool keep_tags = m.tri_tags.size() == m.tri_surface.size();
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* fv = &m.tris[3 * f];
    const FaceKey key = face_key(fv[0], fv[1], fv[2]);
    auto it = face_slot.find(key);
    if (it == face_slot.end())
      throw InputError(what + ": triangle " + s(f + 1) + " is not a face of any tetrahedron");
    if (!have.emplace(key, f).second) continue;
    int tag = m.tri_surface[f];
    if (tag <= 0) {
      const int slot = it->second, o = m.adj[slot];
      if (o < 0)
        tag = fresh.for_boundary();
      else if (m.tet_region[slot / 4] != m.tet_region[o / 4])
        tag = fresh.for_interface();
      else
        continue;
    }
    tris.insert(tris.end(), fv, fv + 3);
    surf.push_back(tag);
    if (keep_tags) tags.push_back(m.tri_tags[f]);
  }
  for (int t = 0; t < nt; ++t)
    for (int f = 0; f < 4; ++f) {
      const int o = m.adj[4 * t + f];
      const bool boundary = o < 0;
      if (!boundary && (o < 4 * t || m.tet_region[t] == m.tet_region[o / 4])) continue;
      const int* tv = &m.tets[4 * t];
      const int a = tv[kTetFace[f][0]], b = tv[kTetFace[f][1]], c = tv[kTetFace[f][2]];
      if (have.count(face_key(a, b, c))) continue;
      tris.insert(tris.end(), {a, b, c});
      surf.push_back(boundary ? fresh.for_boundary() : fresh.for_interface());
      if (keep_tags) tags.push_back(0);
    }
  m.tris = std::move(tris);
  m.tri_surface = std::move(surf);
  m.tri_tags = std::move(tags);

  if (info.entities.empty() || static_cast<int>(m.vclass.size()) != m.nb_vertices()) {
    info.entities.clear();
    info.extra.clear();
    classify3(m, face_slot);
  }
  const MeshCheck c = check_mesh(m);
  if (!c.ok) throw InputError(what + ": invalid tetrahedral mesh: " + check_summary(c));
}

// ---------------------------------------------------------------------------------------------
// 2D

void classify2(TriMesh2& m) {
  const int nv = m.nb_vertices();
  ModelInfo& info = m.model;
  std::vector<std::vector<std::pair<int, int>>> vcurves(nv);  // (curve, degree)
  for (int e = 0; e < m.nb_edges(); ++e)
    for (int k = 0; k < 2; ++k) {
      auto& vc = vcurves[m.edges[2 * e + k]];
      const int c = m.edge_curve[e];
      auto j = std::find_if(vc.begin(), vc.end(), [&](const auto& p) { return p.first == c; });
      if (j == vc.end())
        vc.push_back({c, 1});
      else
        ++j->second;
    }
  std::vector<int> vregion(nv, 0);
  for (int t = 0; t < m.nb_tris(); ++t)
    for (int k = 0; k < 3; ++k)
      if (vregion[m.tris[3 * t + k]] == 0) vregion[m.tris[3 * t + k]] = m.tri_region[t];
  std::map<int, std::vector<int>> curve_corners;
  for (int c : m.edge_curve) curve_corners[c];
  m.vclass.assign(nv, VertexClass{});
  int nb_points = 0;
  for (int v = 0; v < nv; ++v) {
    const auto& vc = vcurves[v];
    if (vc.size() >= 2 || (vc.size() == 1 && vc[0].second != 2)) {
      m.vclass[v] = {0, ++nb_points};
      for (const auto& [c, deg] : vc) curve_corners[c].push_back(nb_points);
      info.entities.push_back({0, nb_points, {}});
      info.extra.push_back({0, nb_points, 15, {0}, {v}});
    } else if (vc.size() == 1) {
      m.vclass[v] = {1, vc[0].first};
    } else {
      m.vclass[v] = {2, vregion[v]};
    }
  }
  for (const auto& [c, corners] : curve_corners) info.entities.push_back({1, c, corners});
  // Which triangles lie along each constrained edge.
  std::unordered_map<EdgeKey, int, EdgeKeyHash> edge_slot;
  for (int t = 0; t < m.nb_tris(); ++t)
    for (int e = 0; e < 3; ++e)
      edge_slot.emplace(edge_key(m.tris[3 * t + (e + 1) % 3], m.tris[3 * t + (e + 2) % 3]),
                        3 * t + e);
  std::map<int, std::vector<int>> region_curves;
  for (int r : m.tri_region) region_curves[r];
  for (int e = 0; e < m.nb_edges(); ++e) {
    const int slot = edge_slot.at(edge_key(m.edges[2 * e], m.edges[2 * e + 1]));
    add_unique(region_curves[m.tri_region[slot / 3]], m.edge_curve[e]);
    if (m.adj[slot] >= 0) add_unique(region_curves[m.tri_region[m.adj[slot] / 3]], m.edge_curve[e]);
  }
  for (auto& [r, curves] : region_curves) {
    std::sort(curves.begin(), curves.end());
    info.entities.push_back({2, r, curves});
  }
}

void finish2(TriMesh2& m, ModelInfo& info, const std::string& what) {
  if (m.xy.size() % 2 != 0) throw InvariantError("finish_mesh: xy is not #V by 2");
  for (std::size_t i = 0; i < m.xy.size(); ++i)
    if (!std::isfinite(m.xy[i]))
      throw InputError(what + ": vertex " + s(i / 2 + 1) + " has a NaN or infinite coordinate");
  if (!std::isfinite(m.z0)) throw InputError(what + ": the plane z coordinate is not finite");
  if (m.tris.empty()) throw InputError(what + " has no triangles (empty mesh)");
  const int nt = m.nb_tris();
  if (static_cast<int>(m.tri_region.size()) != nt) m.tri_region.assign(nt, 1);
  if (m.edge_curve.size() != m.edges.size() / 2) m.edge_curve.assign(m.edges.size() / 2, 0);
  check_ids(m.tris, 3, m.nb_vertices(), what, "triangle");
  check_ids(m.edges, 2, m.nb_vertices(), what, "edge");
  positive_tags(m.tri_region);

  // Orientation per region: a region may be entirely clockwise (stored counter-clockwise).
  std::map<int, std::pair<long, long>> sign;  // region -> (ccw, cw)
  for (int t = 0; t < nt; ++t) {
    const int* v = &m.tris[3 * t];
    const double o = orient2d(m.point(v[0]), m.point(v[1]), m.point(v[2]));
    if (o == 0) throw InputError(what + ": triangle " + s(t + 1) + " is flat (zero area)");
    (o > 0 ? sign[m.tri_region[t]].first : sign[m.tri_region[t]].second)++;
  }
  // A region's turning sense is its triangles' majority (a tie: counter-clockwise); triangles in
  // the other sense are turned to it (the overlap test below says whether they form a mesh).
  m.cw_surfaces.clear();
  long nb_turned = 0;
  for (const auto& [r, c] : sign) {
    if (c.second > c.first) m.cw_surfaces.push_back(r);
    nb_turned += std::min(c.first, c.second);
  }
  for (int t = 0; t < nt; ++t) {
    const int* v = &m.tris[3 * t];
    if (orient2d(m.point(v[0]), m.point(v[1]), m.point(v[2])) < 0)
      std::swap(m.tris[3 * t + 1], m.tris[3 * t + 2]);
  }
  m.model.nb_reoriented = nb_turned;
  if (nb_turned)
    m.model.read_notes.push_back(what + ": " + s(nb_turned) + " of " + s(nt) +
                                 " triangles turned the other way round than their region's "
                                 "majority: turned to it");

  const std::vector<int> map = used_vertices(m.tris, m.nb_vertices());
  for (int& v : m.tris) v = map[v];
  for (std::size_t i = 0; i < m.edges.size(); ++i) {
    const int v = map[m.edges[i]];
    if (v < 0)
      throw InputError(what + ": edge " + s(i / 2 + 1) + " is not an edge of any triangle");
    m.edges[i] = v;
  }
  compact(m.xy, map, 2);
  compact(m.node_tags, map, 1);
  compact(m.vclass, map, 1);

  try {
    build_adjacency2(m);
  } catch (const InputError& e) {
    throw InputError(what + ": " + e.what());
  }
  std::unordered_map<EdgeKey, int, EdgeKeyHash> edge_slot;
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tris[3 * t];
    for (int e = 0; e < 3; ++e) {
      const int a = tv[(e + 1) % 3], b = tv[(e + 2) % 3];
      edge_slot.emplace(edge_key(a, b), 3 * t + e);
      const int o = m.adj[3 * t + e];
      if (o < 0 || o < 3 * t) continue;
      if (orient2d(m.point(a), m.point(b), m.point(m.tris[o])) >= 0)
        throw InputError(what + ": triangles " + s(t + 1) + " and " + s(o / 3 + 1) +
                         " overlap (duplicated or folded elements" +
                         (nb_turned ? "; " + s(nb_turned) +
                                          " triangles were turned to their region's majority "
                                          "sense and do not form a mesh"
                                    : std::string()) +
                         ")");
    }
  }
  FreshTags fresh(m.edge_curve);
  std::vector<int> edges, curve;
  std::vector<std::size_t> tags;
  std::unordered_map<EdgeKey, int, EdgeKeyHash> have;
  const bool keep_tags = m.edge_tags.size() == m.edge_curve.size();
  for (int e = 0; e < m.nb_edges(); ++e) {
    const int a = m.edges[2 * e], b = m.edges[2 * e + 1];
    auto it = edge_slot.find(edge_key(a, b));
    if (it == edge_slot.end())
      throw InputError(what + ": edge " + s(e + 1) + " is not an edge of any triangle");
    if (!have.emplace(edge_key(a, b), e).second) continue;
    int tag = m.edge_curve[e];
    if (tag <= 0) {
      const int slot = it->second, o = m.adj[slot];
      if (o < 0)
        tag = fresh.for_boundary();
      else if (m.tri_region[slot / 3] != m.tri_region[o / 3])
        tag = fresh.for_interface();
      else
        continue;
    }
    edges.insert(edges.end(), {a, b});
    curve.push_back(tag);
    if (keep_tags) tags.push_back(m.edge_tags[e]);
  }
  for (int t = 0; t < nt; ++t)
    for (int e = 0; e < 3; ++e) {
      const int o = m.adj[3 * t + e];
      const bool boundary = o < 0;
      if (!boundary && (o < 3 * t || m.tri_region[t] == m.tri_region[o / 3])) continue;
      const int a = m.tris[3 * t + (e + 1) % 3], b = m.tris[3 * t + (e + 2) % 3];
      if (have.count(edge_key(a, b))) continue;
      edges.insert(edges.end(), {a, b});
      curve.push_back(boundary ? fresh.for_boundary() : fresh.for_interface());
      if (keep_tags) tags.push_back(0);
    }
  m.edges = std::move(edges);
  m.edge_curve = std::move(curve);
  m.edge_tags = std::move(tags);

  if (info.entities.empty() || static_cast<int>(m.vclass.size()) != m.nb_vertices()) {
    info.entities.clear();
    info.extra.clear();
    classify2(m);
  }
  const MeshCheck c = check_mesh(m);
  if (!c.ok) throw InputError(what + ": invalid triangle mesh: " + check_summary(c));
}

}  // namespace

void finish_mesh(MeshData& data, const std::string& what) {
  if (data.dim == 3)
    finish3(data.tet, data.tet.model, what);
  else if (data.dim == 2)
    finish2(data.tri, data.tri.model, what);
  else
    throw InvariantError("finish_mesh: dim must be 2 or 3");
}

}  // namespace cvtmesh
