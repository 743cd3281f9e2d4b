#include "core/mesh/vertex_tets.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/vec3.h"

namespace cvtmesh {
namespace {

// The stars of the vertices v with wanted(v), by counting sort over the live tets.
template <class Wanted>
VertexTets build_stars(const TetMesh& mesh, Wanted wanted) {
  const int nv = mesh.nb_vertices(), nt = mesh.nb_tets();
  VertexTets vt;
  vt.offset.assign(static_cast<std::size_t>(nv) + 1, 0);
  for (int t = 0; t < nt; ++t) {
    const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
    if (tv[0] < 0) continue;
    for (int k = 0; k < 4; ++k)
      if (wanted(tv[k])) ++vt.offset[tv[k] + 1];
  }
  for (int v = 0; v < nv; ++v) vt.offset[v + 1] += vt.offset[v];
  vt.tets.resize(static_cast<std::size_t>(vt.offset[nv]));
  std::vector<int> fill(vt.offset.begin(), vt.offset.end() - 1);
  for (int t = 0; t < nt; ++t) {
    const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
    if (tv[0] < 0) continue;
    for (int k = 0; k < 4; ++k)
      if (wanted(tv[k])) vt.tets[fill[tv[k]]++] = t;
  }
  return vt;
}

}  // namespace

VertexTets vertex_tets(const TetMesh& mesh) {
  return build_stars(mesh, [](int) { return true; });
}

VertexTets vertex_tets_of(const TetMesh& mesh, const std::vector<int>& vertices) {
  std::vector<char> wanted(mesh.nb_vertices(), 0);
  for (int v : vertices) wanted[v] = 1;
  return build_stars(mesh, [&wanted](int v) { return wanted[v] != 0; });
}

double shortest_star_edge(const TetMesh& mesh, const int* b, const int* e, int v) {
  double lmin = std::numeric_limits<double>::infinity();
  const double* P = mesh.point(v);
  for (const int* s = b; s != e; ++s)
    for (int j = 0; j < 4; ++j) {
      const int w = mesh.tets[4 * static_cast<std::size_t>(*s) + j];
      if (w != v) lmin = std::min(lmin, std::sqrt(dist2(P, mesh.point(w))));
    }
  return lmin;
}

}  // namespace cvtmesh
