#include "core/mesh/kept_quads.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

namespace cvtmesh {
namespace {

bool is_quad_block(const ElementBlock& b) {
  return b.dim == 2 && b.gmsh_type == kGmshQuad;
}

double signed_area2(const TriMesh2& m, const int* q) {
  double a = 0;
  for (int k = 0; k < 4; ++k) {
    const double* p = m.point(q[k]);
    const double* r = m.point(q[(k + 1) % 4]);
    a += p[0] * r[1] - p[1] * r[0];
  }
  return a;
}

}  // namespace

KeptQuads kept_quads(const TriMesh2& mesh) {
  KeptQuads k;
  for (const ElementBlock& b : mesh.model.extra) {
    if (!is_quad_block(b)) continue;
    const bool cw = std::binary_search(mesh.cw_surfaces.begin(), mesh.cw_surfaces.end(), b.entity);
    const std::size_t n = b.nodes.size() / 4;
    for (std::size_t e = 0; e < n; ++e) {
      const int* q = &b.nodes[4 * e];
      if (cw)
        k.quads.insert(k.quads.end(), {q[0], q[3], q[2], q[1]});
      else
        k.quads.insert(k.quads.end(), q, q + 4);
      k.entity.push_back(b.entity);
      k.tags.push_back(e < b.tags.size() ? b.tags[e] : 0);
    }
  }
  return k;
}

int orient_quad_surfaces(TriMesh2& mesh) {
  std::set<int> with_tris(mesh.tri_region.begin(), mesh.tri_region.end());
  std::map<int, std::pair<long, long>> sign;  // surface -> (ccw, cw) quadrangles
  for (const ElementBlock& b : mesh.model.extra) {
    if (!is_quad_block(b) || with_tris.count(b.entity)) continue;
    for (std::size_t e = 0; 4 * e < b.nodes.size(); ++e)
      (signed_area2(mesh, &b.nodes[4 * e]) < 0 ? sign[b.entity].second : sign[b.entity].first)++;
  }
  int n = 0;
  for (const auto& [s, c] : sign)
    if (c.second > c.first &&
        !std::binary_search(mesh.cw_surfaces.begin(), mesh.cw_surfaces.end(), s)) {
      mesh.cw_surfaces.push_back(s);
      ++n;
    }
  std::sort(mesh.cw_surfaces.begin(), mesh.cw_surfaces.end());
  return n;
}

}  // namespace cvtmesh
