#include "core/boundary/discrete_boundary.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "core/boundary/triangle_set_distance.h"
#include "core/geometry/vec3.h"

namespace cvtmesh {
namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(static_cast<std::size_t>(n)) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

class DiscreteGeometry final : public BoundaryGeometry {
 public:
  std::vector<double> xyz;  // the input's coordinates
  std::vector<std::unique_ptr<TriangleSetDistance>> patches;
  std::vector<std::unique_ptr<SegmentSetDistance>> curves;
  std::unique_ptr<TriangleSetDistance> all;
  std::vector<int> tris;  // all boundary triangles

  bool closest_on_surface(int s, const double* p, double* q) const override {
    if (s < 0 || s >= static_cast<int>(patches.size())) return false;
    return patches[s]->closest(p, q);
  }
  bool closest_on_curve(int c, const double* p, double* q) const override {
    if (c < 0 || c >= static_cast<int>(curves.size())) return false;
    return curves[c]->closest(p, q);
  }
  double distance_to_boundary(const double* p) const override { return all->distance(p); }
  bool within_distance(const double* p, double r) const override { return all->any_within(p, r); }
  std::vector<double> samples() const override {
    // The input's boundary vertices, edge midpoints and triangle centroids.
    std::vector<double> s;
    std::vector<char> seen(xyz.size() / 3, 0);
    for (std::size_t f = 0; f + 2 < tris.size(); f += 3) {
      double c[3] = {0, 0, 0};
      for (int k = 0; k < 3; ++k) {
        const int a = tris[f + k], b = tris[f + (k + 1) % 3];
        for (int d = 0; d < 3; ++d) {
          c[d] += xyz[3 * a + d] / 3;
          if (a < b) s.push_back(0.5 * (xyz[3 * a + d] + xyz[3 * b + d]));
        }
        if (!seen[a]) {
          seen[a] = 1;
          s.insert(s.end(), &xyz[3 * a], &xyz[3 * a] + 3);
        }
      }
      s.insert(s.end(), c, c + 3);
    }
    return s;
  }
  const char* kind() const override { return "discrete"; }
};

Vec3 tri_normal(const std::vector<double>& xyz, int a, int b, int c) {
  const Vec3 n = cross(sub(&xyz[3 * b], &xyz[3 * a]), sub(&xyz[3 * c], &xyz[3 * a]));
  const double l = norm(n);
  return l > 0 ? (1 / l) * n : Vec3{0, 0, 0};
}

}  // namespace

BoundaryModel make_discrete_boundary(const TetMesh& m, const BoundaryModelOptions& o) {
  if (!(o.feature_angle >= 0))
    throw std::invalid_argument("make_discrete_boundary: feature_angle must be >= 0");
  const int nv = m.nb_vertices(), nf = m.nb_tris();
  const double cos_feature = std::cos(o.feature_angle * 3.14159265358979323846 / 180);
  // Edges: (min, max, triangle), sorted.
  std::vector<std::array<int, 3>> edges;
  edges.reserve(3 * static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.tris[3 * f + k], b = m.tris[3 * f + (k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), f});
    }
  std::sort(edges.begin(), edges.end());
  // Does triangle f run along a -> b (as opposed to b -> a)?
  auto runs = [&](int f, int a, int b) {
    for (int k = 0; k < 3; ++k)
      if (m.tris[3 * f + k] == a && m.tris[3 * f + (k + 1) % 3] == b) return true;
    return false;
  };
  UnionFind patch_uf(nf);
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1]) ++j;
    if (j - i == 2) {
      const int f = edges[i][2], g = edges[i + 1][2], a = edges[i][0], b = edges[i][1];
      if (m.tri_surface[f] == m.tri_surface[g] || o.free_smooth_curves) {
        Vec3 nf_ = tri_normal(m.xyz, m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]);
        Vec3 ng = tri_normal(m.xyz, m.tris[3 * g], m.tris[3 * g + 1], m.tris[3 * g + 2]);
        // Consistently oriented neighbours run along their common edge in opposite directions.
        if (runs(f, a, b) == runs(g, a, b)) ng = -1.0 * ng;
        if (dot(nf_, ng) >= cos_feature) patch_uf.unite(f, g);
      }
    }
    i = j;
  }
  // Patch ids 0.., per triangle.
  std::vector<int> patch(static_cast<std::size_t>(nf)), root_id(static_cast<std::size_t>(nf), -1);
  int nb_patches = 0;
  for (int f = 0; f < nf; ++f) {
    const int r = patch_uf.find(f);
    if (root_id[r] < 0) root_id[r] = nb_patches++;
    patch[f] = root_id[r];
  }
  // Feature edges: between two patches, or not shared by exactly two triangles.
  std::vector<std::array<int, 2>> feature;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    bool same = true;
    while (j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1]) {
      same &= patch[edges[j][2]] == patch[edges[i][2]];
      ++j;
    }
    if (j - i != 2 || !same) feature.push_back({edges[i][0], edges[i][1]});
    i = j;
  }
  std::vector<int> feature_degree(static_cast<std::size_t>(nv), 0);
  for (const auto& e : feature) {
    ++feature_degree[e[0]];
    ++feature_degree[e[1]];
  }
  // Locked vertices.
  std::vector<char> locked(static_cast<std::size_t>(nv), 0), on_boundary(locked.size(), 0);
  std::vector<int> vpatch(static_cast<std::size_t>(nv), -1);
  std::vector<char> multi_patch(locked.size(), 0);
  for (int f = 0; f < nf; ++f) {
    const bool lock = std::find(o.locked_surfaces.begin(), o.locked_surfaces.end(),
                                m.tri_surface[f]) != o.locked_surfaces.end();
    for (int k = 0; k < 3; ++k) {
      const int v = m.tris[3 * f + k];
      on_boundary[v] = 1;
      if (lock) locked[v] = 1;
      if (vpatch[v] < 0)
        vpatch[v] = patch[f];
      else if (vpatch[v] != patch[f])
        multi_patch[v] = 1;
    }
  }
  BoundaryModel out;
  out.role.assign(static_cast<std::size_t>(nv), VertexRole{});
  auto curve_vertex = [&](int v) {
    const VertexClass c = m.vclass[v];
    if (locked[v] || (c.dim == 0 && !o.free_smooth_curves) || feature_degree[v] != 2) return false;
    if (c.dim == 1 && std::find(o.locked_curves.begin(), o.locked_curves.end(), c.entity) !=
                          o.locked_curves.end())
      return false;
    return true;
  };
  // Chains: feature edges joined through curve vertices.
  UnionFind chain_uf(static_cast<int>(feature.size()));
  {
    std::vector<int> first(static_cast<std::size_t>(nv), -1);
    for (int e = 0; e < static_cast<int>(feature.size()); ++e)
      for (int k = 0; k < 2; ++k) {
        const int v = feature[e][k];
        if (!curve_vertex(v)) continue;
        if (first[v] < 0)
          first[v] = e;
        else
          chain_uf.unite(first[v], e);
      }
  }
  std::vector<int> chain(feature.size()), chain_root(feature.size(), -1);
  int nb_chains = 0;
  for (int e = 0; e < static_cast<int>(feature.size()); ++e) {
    const int r = chain_uf.find(e);
    if (chain_root[r] < 0) chain_root[r] = nb_chains++;
    chain[e] = chain_root[r];
  }
  std::vector<int> vchain(static_cast<std::size_t>(nv), -1);
  for (int e = 0; e < static_cast<int>(feature.size()); ++e)
    for (int k = 0; k < 2; ++k) vchain[feature[e][k]] = chain[e];
  for (int v = 0; v < nv; ++v) {
    VertexRole& r = out.role[v];
    if (!on_boundary[v]) {
      r.role = m.vclass[v].dim < 3 ? BoundaryRole::kFixed : BoundaryRole::kInterior;
      continue;
    }
    const VertexClass c = m.vclass[v];
    if (locked[v] || (c.dim == 0 && !o.free_smooth_curves) || c.dim == 3) {
      r.role = BoundaryRole::kFixed;
    } else if (feature_degree[v] == 0 && !multi_patch[v] && (c.dim == 2 || o.free_smooth_curves)) {
      r = {BoundaryRole::kSurface, vpatch[v]};
    } else if (curve_vertex(v)) {
      r = {BoundaryRole::kCurve, vchain[v]};
    } else {
      r.role = BoundaryRole::kFixed;
    }
    if (r.role == BoundaryRole::kSurface) ++out.nb_surface_vertices;
    if (r.role == BoundaryRole::kCurve) ++out.nb_curve_vertices;
    if (r.role == BoundaryRole::kFixed) ++out.nb_fixed_vertices;
  }
  // The geometry: one triangle set per patch, one segment set per chain, one for everything.
  auto g = std::make_shared<DiscreteGeometry>();
  g->xyz = m.xyz;
  g->tris = m.tris;
  std::vector<std::vector<int>> ptris(static_cast<std::size_t>(nb_patches));
  for (int f = 0; f < nf; ++f)
    ptris[patch[f]].insert(ptris[patch[f]].end(), &m.tris[3 * f], &m.tris[3 * f] + 3);
  for (const auto& t : ptris) g->patches.push_back(std::make_unique<TriangleSetDistance>(m.xyz, t));
  std::vector<std::vector<int>> csegs(static_cast<std::size_t>(nb_chains));
  for (int e = 0; e < static_cast<int>(feature.size()); ++e)
    csegs[chain[e]].insert(csegs[chain[e]].end(), feature[e].begin(), feature[e].end());
  for (const auto& s : csegs) g->curves.push_back(std::make_unique<SegmentSetDistance>(m.xyz, s));
  g->all = std::make_unique<TriangleSetDistance>(m.xyz, m.tris);
  out.curve_edges = feature;  // sorted, smaller id first (from the sorted edge list)
  out.curve_edges_known = true;
  out.geometry = g;
  out.diagonal = bounding_box_diagonal(m);
  out.input_xyz = m.xyz;
  return out;
}

}  // namespace cvtmesh
