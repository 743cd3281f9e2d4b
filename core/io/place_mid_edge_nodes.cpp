#include "core/io/place_mid_edge_nodes.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/geometry/tet10_positive.h"
#include "core/geometry/tri6_positive.h"
#include "core/mesh/constrain_kept_cell_faces.h"

namespace cvtmesh {
namespace {

using Key = std::uint64_t;  // (smaller vertex id) << 32 | larger

Key edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<Key>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

struct TagPairHash {
  std::size_t operator()(const std::pair<std::size_t, std::size_t>& p) const {
    return std::hash<std::size_t>()(p.first * 0x9e3779b97f4a7c15ULL ^ p.second);
  }
};

// Every edge of the mesh with the entity of lowest dimension it lies on.
using EdgeMap = std::map<Key, VertexClass>;

void add_edge(EdgeMap& edges, int a, int b, int dim, int entity) {
  auto [it, fresh] =
      edges.emplace(edge_key(a, b), VertexClass{static_cast<std::int8_t>(dim), entity});
  if (!fresh && dim < it->second.dim) it->second = {static_cast<std::int8_t>(dim), entity};
}

std::uint64_t fingerprint(const std::vector<double>& coordinates, double extra) {
  std::uint64_t h = 1469598103934665603ULL;
  const unsigned char* p = reinterpret_cast<const unsigned char*>(coordinates.data());
  const std::size_t n = coordinates.size() * sizeof(double);
  for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ULL;
  const unsigned char* q = reinterpret_cast<const unsigned char*>(&extra);
  if (extra != 0)
    for (std::size_t i = 0; i < sizeof extra; ++i) h = (h ^ q[i]) * 1099511628211ULL;
  return h ^ coordinates.size();
}

// The working state of one placement: the placement, which nodes are off their straight
// midpoint, and the count each node is in.
struct Placing {
  MidEdgePlacement out;
  std::vector<char> curved;
  std::vector<int*> category;
};

// Places one node per edge by the rules of place_mid_edge_nodes.h. dim: the mesh's (3, or 2 for
// a planar mesh): an edge on an entity of lower dimension is a boundary edge, the corners'
// first dim coordinates decide whether they moved, and only those coordinates are projected or
// offset (a planar mesh's nodes stay in its plane). point(v, p) writes vertex v's 3 coordinates.
template <class Point>
void place_nodes(const EdgeMap& edges, int dim, const Point& point,
                 const std::vector<std::size_t>& node_tags, const MidEdgeNodes& in,
                 const MidEdgeProjector& project, Placing& s) {
  MidEdgePlacement& out = s.out;
  // The input's nodes by their corners' tags.
  std::unordered_map<std::pair<std::size_t, std::size_t>, int, TagPairHash> input;
  input.reserve(in.tags.size() * 2);
  for (std::size_t i = 0; i < in.tags.size(); ++i)
    input.emplace(std::make_pair(in.corner_tags[2 * i], in.corner_tags[2 * i + 1]),
                  static_cast<int>(i));
  auto tag_of = [&](int v) -> std::size_t {
    return v < static_cast<int>(node_tags.size()) ? node_tags[v] : 0;
  };

  const std::size_t ne = edges.size();
  out.edges.reserve(2 * ne);
  out.tags.assign(ne, 0);
  out.xyz.resize(3 * ne);
  out.where.reserve(ne);
  s.curved.assign(ne, 0);          // not on the straight midpoint
  s.category.assign(ne, nullptr);  // the count it is in
  std::size_t k = 0;
  for (const auto& [key, where] : edges) {
    const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
    out.edges.push_back(a);
    out.edges.push_back(b);
    out.where.push_back(where);
    double pa[3], pb[3];
    point(a, pa);
    point(b, pb);
    double* x = &out.xyz[3 * k];
    for (int c = 0; c < 3; ++c) x[c] = 0.5 * (pa[c] + pb[c]);
    // The input's node of this edge, if any (corners by tag, smaller first).
    int src = -1;
    const double* qa = pa;
    const double* qb = pb;
    std::size_t ta = tag_of(a), tb = tag_of(b);
    if (ta && tb) {
      if (ta > tb) {
        std::swap(ta, tb);
        std::swap(qa, qb);
      }
      if (auto it = input.find({ta, tb}); it != input.end()) src = it->second;
    }
    if (src >= 0) {
      out.tags[k] = in.tags[src];
      const double* ca = &in.corner_xyz[6 * src];
      const bool unmoved = std::memcmp(ca, qa, dim * sizeof(double)) == 0 &&
                           std::memcmp(ca + 3, qb, dim * sizeof(double)) == 0;
      if (unmoved) {
        for (int c = 0; c < 3; ++c) {
          x[c] = in.xyz[3 * src + c];
          s.curved[k] |= x[c] != 0.5 * (pa[c] + pb[c]);
        }
        ++out.nb_kept;
        s.category[k] = &out.nb_kept;
        ++k;
        continue;
      }
    }
    double projected[3];
    if (where.dim < dim && project && project(where.dim, where.entity, x, projected)) {
      for (int c = 0; c < dim; ++c) x[c] = projected[c];
      s.curved[k] = 1;
      ++out.nb_cad;
      s.category[k] = &out.nb_cad;
    } else if (where.dim < dim && src >= 0) {
      const double* ca = &in.corner_xyz[6 * src];
      for (int c = 0; c < dim; ++c) x[c] += in.xyz[3 * src + c] - 0.5 * (ca[c] + ca[3 + c]);
      s.curved[k] = 1;
      ++out.nb_curved;
      s.category[k] = &out.nb_curved;
    } else {
      ++out.nb_straight;
      s.category[k] = &out.nb_straight;
    }
    ++k;
  }
}

// The index in out.edges (sorted by pair) of the edge (a, b).
int edge_index(const MidEdgePlacement& out, int a, int b) {
  if (a > b) std::swap(a, b);
  std::size_t lo = 0, hi = out.tags.size();
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    const int ma = out.edges[2 * mid], mb = out.edges[2 * mid + 1];
    if (ma < a || (ma == a && mb < b))
      lo = mid + 1;
    else
      hi = mid;
  }
  return static_cast<int>(lo);
}

// Validity of every element (cell_edges: epc node indices per element, -1 for a dead one), then
// the fallback to straight nodes where an element fails (place_mid_edge_nodes.h).
template <class Point, class Positive>
void check_elements(Placing& s, const std::vector<int>& cell_edges, int epc, const Point& point,
                    const Positive& positive, bool fallback) {
  MidEdgePlacement& out = s.out;
  const int nt = static_cast<int>(cell_edges.size() / epc);
  std::vector<std::vector<int>> edge_cells(out.tags.size());
  for (int t = 0; t < nt; ++t)
    if (cell_edges[epc * t] >= 0)
      for (int e = 0; e < epc; ++e)
        if (s.curved[cell_edges[epc * t + e]]) edge_cells[cell_edges[epc * t + e]].push_back(t);
  std::vector<int> queue;
  for (int t = 0; t < nt; ++t)
    if (cell_edges[epc * t] >= 0) {
      bool any = false;
      for (int e = 0; e < epc; ++e) any |= s.curved[cell_edges[epc * t + e]] != 0;
      if (any) queue.push_back(t);
    }
  if (!fallback) queue.clear();
  while (!queue.empty()) {
    const int t = queue.back();
    queue.pop_back();
    if (positive(t)) continue;
    for (int e = 0; e < epc; ++e) {
      const int i = cell_edges[epc * t + e];
      if (!s.curved[i]) continue;
      s.curved[i] = 0;
      double pa[3], pb[3];
      point(out.edges[2 * i], pa);
      point(out.edges[2 * i + 1], pb);
      for (int c = 0; c < 3; ++c) out.xyz[3 * i + c] = 0.5 * (pa[c] + pb[c]);
      ++out.nb_fallback;
      --*s.category[i];
      ++out.nb_straight;
      s.category[i] = &out.nb_straight;
      for (int u : edge_cells[i])
        if (u != t) queue.push_back(u);
    }
  }
  for (int t = 0; t < nt; ++t)
    if (cell_edges[epc * t] >= 0 && !positive(t)) ++out.nb_invalid;
}

}  // namespace

std::uint64_t mid_edge_fingerprint(const TetMesh& mesh) {
  return fingerprint(mesh.xyz, 0);
}

std::uint64_t mid_edge_fingerprint(const TriMesh2& mesh) {
  return fingerprint(mesh.xy, mesh.z0);
}

MidEdgePlacement place_mid_edge_nodes(const TetMesh& mesh, const MidEdgeProjector& project,
                                      bool fallback) {
  Placing s;
  s.out.fingerprint = mid_edge_fingerprint(mesh);
  EdgeMap edges;
  for (int t = 0; t < mesh.nb_tets(); ++t) {
    const int* v = &mesh.tets[4 * t];
    if (v[0] < 0) continue;
    for (const auto& e : kTet10Edge) add_edge(edges, v[e[0]], v[e[1]], 3, mesh.tet_region[t]);
  }
  for (int f = 0; f < mesh.nb_tris(); ++f) {
    const int* v = &mesh.tris[3 * f];
    if (v[0] < 0) continue;
    const int srf = mesh.tri_surface[f];
    const int dim = is_kept_cell_interface(srf) ? 3 : 2;
    for (int k = 0; k < 3; ++k) add_edge(edges, v[k], v[(k + 1) % 3], dim, dim == 2 ? srf : 0);
  }
  for (const ElementBlock& b : mesh.model.extra) {
    if (b.gmsh_type == 1)
      for (std::size_t e = 0; 2 * e + 1 < b.nodes.size(); ++e)
        add_edge(edges, b.nodes[2 * e], b.nodes[2 * e + 1], 1, b.entity);
    if (b.gmsh_type == 2)
      for (std::size_t e = 0; 3 * e + 2 < b.nodes.size(); ++e)
        for (int k = 0; k < 3; ++k)
          add_edge(edges, b.nodes[3 * e + k], b.nodes[3 * e + (k + 1) % 3], 2, b.entity);
  }
  // A surface edge whose corners lie on one curve (a curve's vertices, or its end points) is on
  // that curve: inputs saved without their curves' line elements (a .msh with physical groups
  // on surfaces and volumes only) still get their curve nodes on the curve.
  std::map<int, std::vector<int>> curves_of_point;  // point tag -> curves it bounds
  for (const ModelEntity& e : mesh.model.entities)
    if (e.dim == 1)
      for (int p : e.boundary) curves_of_point[p < 0 ? -p : p].push_back(e.tag);
  auto on_curve = [&](const VertexClass& a, const VertexClass& b) {
    auto bounds = [&](int point, int curve) {
      auto it = curves_of_point.find(point);
      return it != curves_of_point.end() &&
             std::find(it->second.begin(), it->second.end(), curve) != it->second.end();
    };
    if (a.dim == 1 && b.dim == 1) return a.entity == b.entity ? a.entity : 0;
    if (a.dim == 1 && b.dim == 0) return bounds(b.entity, a.entity) ? a.entity : 0;
    if (a.dim == 0 && b.dim == 1) return bounds(a.entity, b.entity) ? b.entity : 0;
    if (a.dim == 0 && b.dim == 0 && a.entity != b.entity) {
      auto it = curves_of_point.find(a.entity);
      if (it != curves_of_point.end())
        for (int c : it->second)
          if (bounds(b.entity, c)) return c;
    }
    return 0;
  };
  if (mesh.vclass.size() == static_cast<std::size_t>(mesh.nb_vertices()))
    for (auto& [key, where] : edges) {
      if (where.dim != 2) continue;
      const int a = static_cast<int>(key >> 32), b = static_cast<int>(key & 0xffffffffu);
      if (const int c = on_curve(mesh.vclass[a], mesh.vclass[b])) where = {1, c};
    }
  auto point = [&](int v, double* p) {
    const double* q = mesh.point(v);
    p[0] = q[0];
    p[1] = q[1];
    p[2] = q[2];
  };
  place_nodes(edges, 3, point, mesh.node_tags, mesh.model.high_order, project, s);

  // Validity: the tets' 10 nodes, then the fallback to straight nodes where a tet fails.
  const int nt = mesh.nb_tets();
  std::vector<int> tet_edges(6 * static_cast<std::size_t>(nt), -1);
  for (int t = 0; t < nt; ++t) {
    const int* v = &mesh.tets[4 * t];
    if (v[0] < 0) continue;
    for (int e = 0; e < 6; ++e)
      tet_edges[6 * t + e] = edge_index(s.out, v[kTet10Edge[e][0]], v[kTet10Edge[e][1]]);
  }
  auto positive = [&](int t) {
    const int* v = &mesh.tets[4 * t];
    const double* c[4] = {mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])};
    const double* m[6];
    for (int e = 0; e < 6; ++e) m[e] = &s.out.xyz[3 * tet_edges[6 * t + e]];
    return tet10_positive(c, m);
  };
  check_elements(s, tet_edges, 6, point, positive, fallback);
  return std::move(s.out);
}

MidEdgePlacement place_mid_edge_nodes(const TriMesh2& mesh, const MidEdgeProjector& project,
                                      bool fallback) {
  Placing s;
  s.out.fingerprint = mid_edge_fingerprint(mesh);
  EdgeMap edges;
  for (int t = 0; t < mesh.nb_tris(); ++t) {
    const int* v = &mesh.tris[3 * t];
    if (v[0] < 0) continue;
    for (const auto& e : kTri6Edge) add_edge(edges, v[e[0]], v[e[1]], 2, mesh.tri_region[t]);
  }
  for (int e = 0; e < mesh.nb_edges(); ++e) {
    const int* v = &mesh.edges[2 * e];
    if (v[0] < 0) continue;
    add_edge(edges, v[0], v[1], 1, mesh.edge_curve[e]);
  }
  auto point = [&](int v, double* p) {
    const double* q = mesh.point(v);
    p[0] = q[0];
    p[1] = q[1];
    p[2] = mesh.z0;
  };
  place_nodes(edges, 2, point, mesh.node_tags, mesh.model.high_order, project, s);

  // Validity: the triangles' 6 nodes, then the fallback to straight nodes where one fails.
  const int nt = mesh.nb_tris();
  std::vector<int> tri_edges(3 * static_cast<std::size_t>(nt), -1);
  for (int t = 0; t < nt; ++t) {
    const int* v = &mesh.tris[3 * t];
    if (v[0] < 0) continue;
    for (int e = 0; e < 3; ++e)
      tri_edges[3 * t + e] = edge_index(s.out, v[kTri6Edge[e][0]], v[kTri6Edge[e][1]]);
  }
  auto positive = [&](int t) {
    const int* v = &mesh.tris[3 * t];
    const double* c[3] = {mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2])};
    const double* m[3];
    for (int e = 0; e < 3; ++e) m[e] = &s.out.xyz[3 * tri_edges[3 * t + e]];
    return tri6_positive(c, m);
  };
  check_elements(s, tri_edges, 3, point, positive, fallback);
  return std::move(s.out);
}

const MidEdgePlacement& place_mid_edge_nodes(MeshData& data, const MidEdgeProjector& project) {
  MidEdgePlacement& p = data.model().high_order.placed;
  p = data.dim == 3 ? place_mid_edge_nodes(data.tet, project)
                    : place_mid_edge_nodes(data.tri, project);
  return p;
}

std::string mid_edge_summary(const MidEdgePlacement& p) {
  const std::size_t n = p.tags.size();
  std::string s = "order-2 mesh: " + std::to_string(n) +
                  " mid-edge nodes: " + std::to_string(p.nb_kept) + " kept from the input";
  if (p.nb_cad) s += ", " + std::to_string(p.nb_cad) + " projected on the CAD";
  if (p.nb_curved)
    s += ", " + std::to_string(p.nb_curved) + " on the input's curved boundary (offset carried)";
  s += ", " + std::to_string(p.nb_straight) + " at the straight edge midpoint";
  if (p.nb_fallback)
    s += "; " + std::to_string(p.nb_fallback) +
         " curved nodes put back on the straight midpoint because the element would invert";
  if (p.nb_invalid)
    s += "; " + std::to_string(p.nb_invalid) + " elements not positive even with straight edges";
  return s;
}

}  // namespace cvtmesh
