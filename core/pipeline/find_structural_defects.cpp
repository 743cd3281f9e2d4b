#include "core/pipeline/find_structural_defects.h"

#include <cstdio>

#include "core/mesh/find_coincident_vertices.h"
#include "core/mesh/find_surface_intersections.h"

namespace cvtmesh {
namespace {

std::string point_text(const double* p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.9g, %.9g, %.9g)", p[0], p[1], p[2]);
  return buf;
}

std::string node_text(const TetMesh& m, int v) {
  const std::size_t tag =
      v < static_cast<int>(m.node_tags.size()) && m.node_tags[v] ? m.node_tags[v] : v + 1;
  return "node " + std::to_string(tag) + " " + point_text(m.point(v));
}

std::string tri_text(const TetMesh& m, int f) {
  const std::size_t tag =
      f < static_cast<int>(m.tri_tags.size()) && m.tri_tags[f] ? m.tri_tags[f] : f + 1;
  return "triangle " + std::to_string(tag) + " of surface " + std::to_string(m.tri_surface[f]);
}

}  // namespace

StructuralDefects find_structural_defects(const TetMesh& m, double relative_tolerance) {
  StructuralDefects d;
  std::vector<char> used(m.nb_vertices(), 0);
  for (int v : m.tets)
    if (v >= 0) used[v] = 1;
  for (int v : m.tris) used[v] = 1;
  d.coincident_vertices = find_coincident_vertices(m.xyz, used, relative_tolerance);
  d.intersecting_tris = find_surface_intersections(m.xyz, m.tris);
  return d;
}

std::vector<std::string> StructuralDefects::describe(const TetMesh& m) const {
  std::vector<std::string> out;
  if (!intersecting_tris.empty()) {
    const auto [f, g] = intersecting_tris.front();
    double c[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k)
      for (int e = 0; e < 3; ++e) c[e] += m.point(m.tris[3 * f + k])[e] / 3;
    out.push_back(std::to_string(intersecting_tris.size()) +
                  (intersecting_tris.size() >= 1000 ? "+" : "") +
                  " pairs of boundary/interface triangles intersect (the surface mesh "
                  "self-intersects; first: " +
                  tri_text(m, f) + " and " + tri_text(m, g) + ", near " + point_text(c) + ")");
  }
  if (!coincident_vertices.empty()) {
    const auto [a, b] = coincident_vertices.front();
    out.push_back(std::to_string(coincident_vertices.size()) +
                  (coincident_vertices.size() >= 1000 ? "+" : "") +
                  " pairs of distinct nodes coincide or nearly (closer than 1e-8 of the "
                  "diagonal; first: " +
                  node_text(m, a) + " and " + node_text(m, b) + ")");
  }
  return out;
}

}  // namespace cvtmesh
