#include "core/mesh/check_surface_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <unordered_map>

#include "core/geometry/predicates.h"
#include "core/geometry/vec3.h"
#include "core/mesh/face_key.h"

namespace cvtmesh {
namespace {

void problem(MeshCheck& r, const std::string& msg) {
  r.ok = false;
  if (r.problems.size() < 40) r.problems.push_back(msg);
}

// Exactly collinear: zero area in each of the three coordinate projections.
bool flat_triangle(const double* a, const double* b, const double* c) {
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3;
    const double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
    if (orient2d(pa, pb, pc) != 0) return false;
  }
  return true;
}

}  // namespace

MeshCheck check_surface_mesh(const TetMesh& m) {
  MeshCheck r;
  const int nv = m.nb_vertices(), nf = m.nb_tris();
  if (static_cast<int>(m.tri_surface.size()) != nf) problem(r, "tri_surface size differs from #F");
  if (static_cast<int>(m.vclass.size()) != nv) problem(r, "vclass size differs from #V");
  // Keys: the sorted vertices and the surface (two surfaces of one curve loop, e.g. fillings of
  // one contour, may share a corner triangle).
  std::unordered_map<FaceKey, std::vector<int>, FaceKeyHash> seen;
  seen.reserve(2 * static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f) {
    const int* v = &m.tris[3 * f];
    if (v[0] < 0) continue;
    bool in_range = true;
    for (int k = 0; k < 3; ++k) in_range = in_range && v[k] >= 0 && v[k] < nv;
    if (!in_range) {
      problem(r, "triangle " + std::to_string(f) + " has a vertex id out of range");
      continue;
    }
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] ||
        flat_triangle(m.point(v[0]), m.point(v[1]), m.point(v[2]))) {
      ++r.nb_inverted;
      problem(r, "triangle " + std::to_string(f) + " is flat (zero area)");
    }
    std::vector<int>& same = seen[face_key(v[0], v[1], v[2])];
    for (int g : same)
      if (m.tri_surface[g] == m.tri_surface[f]) {
        ++r.nb_bad_adjacency;
        problem(r, "triangles " + std::to_string(g) + " and " + std::to_string(f) + " of surface " +
                       std::to_string(m.tri_surface[f]) +
                       " have the same three vertices (duplicate triangle)");
      }
    same.push_back(f);
  }
  return r;
}

std::vector<std::array<int, 2>> folded_triangle_pairs(const TetMesh& m, double max_turn_degrees) {
  const double cos_limit = std::cos(max_turn_degrees * M_PI / 180);
  // Edge -> the triangles on it (the first two; a third marks it non-manifold).
  std::unordered_map<EdgeKey, std::array<int, 3>, EdgeKeyHash> on_edge;
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* v = &m.tris[3 * f];
    if (v[0] < 0) continue;
    for (int k = 0; k < 3; ++k) {
      auto [it, fresh] =
          on_edge.emplace(edge_key(v[k], v[(k + 1) % 3]), std::array<int, 3>{f, -1, -1});
      if (fresh) continue;
      if (it->second[1] < 0)
        it->second[1] = f;
      else
        it->second[2] = f;
    }
  }
  auto normal = [&](int f) {
    const int* v = &m.tris[3 * f];
    return cross(sub(m.point(v[1]), m.point(v[0])), sub(m.point(v[2]), m.point(v[0])));
  };
  // Whether triangle f runs a -> b (rather than b -> a).
  auto runs = [&](int f, int a, int b) {
    const int* v = &m.tris[3 * f];
    for (int k = 0; k < 3; ++k)
      if (v[k] == a) return v[(k + 1) % 3] == b;
    return false;
  };
  std::vector<std::array<int, 2>> out;
  for (const auto& [e, fs] : on_edge) {
    if (fs[1] < 0 || fs[2] >= 0) continue;
    const int f = fs[0], g = fs[1];
    if (m.tri_surface[f] != m.tri_surface[g]) continue;
    Vec3 nf = normal(f), ng = normal(g);
    if (runs(f, e[0], e[1]) == runs(g, e[0], e[1])) ng = -1.0 * ng;
    const double l = norm(nf) * norm(ng);
    if (l > 0 && dot(nf, ng) < cos_limit * l) out.push_back({std::min(f, g), std::max(f, g)});
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace cvtmesh
