#include "core/boundary/restore_crossing_vertices.h"

#include <algorithm>
#include <array>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/mesh/find_surface_intersections.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {
namespace {

std::vector<int> live_tris(const TetMesh& m) {
  std::vector<int> t;
  for (int f = 0; f < m.nb_tris(); ++f)
    if (m.tris[3 * f] >= 0) t.insert(t.end(), &m.tris[3 * f], &m.tris[3 * f] + 3);
  return t;
}

bool star_positive(const TetMesh& m, const VertexTets& star, int v) {
  for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) {
    const int* tv = &m.tets[4 * static_cast<std::size_t>(*t)];
    if (orient3d(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])) <= 0) return false;
  }
  return true;
}

}  // namespace

RestoreCrossingStats restore_crossing_vertices(TetMesh& mesh, const TetMesh& input,
                                               int max_rounds) {
  RestoreCrossingStats st;
  const std::vector<int> tris = live_tris(mesh);
  auto crossings = find_surface_intersections(mesh.xyz, tris, 1000);
  st.nb_pairs_before = st.nb_pairs_after = static_cast<long>(crossings.size());
  if (crossings.empty() || !find_surface_intersections(input.xyz, live_tris(input), 1).empty())
    return st;
  const VertexTets star = vertex_tets(mesh);
  const int nv = mesh.nb_vertices(), n_in = std::min(nv, input.nb_vertices());
  // Boundary vertex -> its boundary triangles (for the rings).
  std::vector<int> offset(nv + 1, 0), around;
  for (int v : tris) ++offset[v + 1];
  for (int v = 0; v < nv; ++v) offset[v + 1] += offset[v];
  around.resize(offset[nv]);
  {
    std::vector<int> fill(offset.begin(), offset.end() - 1);
    for (std::size_t k = 0; k < tris.size(); ++k) around[fill[tris[k]]++] = static_cast<int>(k / 3);
  }
  std::vector<char> chosen(nv, 0);
  for (int round = 0; round <= max_rounds && !crossings.empty(); ++round) {
    ++st.rounds;
    // The vertices of the crossing triangles, then `round` rings of boundary neighbours.
    std::vector<int> set;
    for (const auto& pair : crossings)
      for (int f : pair)
        for (int k = 0; k < 3; ++k) set.push_back(tris[3 * f + k]);
    for (int ring = 0; ring < round; ++ring) {
      const std::size_t n = set.size();
      for (std::size_t i = 0; i < n; ++i)
        for (int a = offset[set[i]]; a < offset[set[i] + 1]; ++a)
          for (int k = 0; k < 3; ++k) set.push_back(tris[3 * around[a] + k]);
    }
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
    for (int v : set) {
      if (v >= n_in || chosen[v]) continue;
      const double* home = input.point(v);
      double* p = mesh.point(v);
      if (p[0] == home[0] && p[1] == home[1] && p[2] == home[2]) continue;
      const std::array<double, 3> old{p[0], p[1], p[2]};
      std::copy(home, home + 3, p);
      if (star_positive(mesh, star, v)) {
        chosen[v] = 1;
        ++st.nb_restored;
      } else {
        std::copy(old.begin(), old.end(), p);
      }
    }
    crossings = find_surface_intersections(mesh.xyz, tris, 1000);
  }
  st.nb_pairs_after = static_cast<long>(crossings.size());
  return st;
}

}  // namespace cvtmesh
