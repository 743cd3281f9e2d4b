#include "core/boundary/restore_boundary_vertices.h"

#include <algorithm>
#include <array>

#include "core/geometry/predicates.h"

namespace cvtmesh {

std::vector<int> live_boundary_tris(const TetMesh& m) {
  std::vector<int> t;
  for (int f = 0; f < m.nb_tris(); ++f)
    if (m.tris[3 * f] >= 0) t.insert(t.end(), &m.tris[3 * f], &m.tris[3 * f] + 3);
  return t;
}

std::vector<int> boundary_rings(int nv, const std::vector<int>& tris, std::vector<int> set,
                                int rings) {
  std::vector<int> offset(nv + 1, 0), around;
  for (int v : tris) ++offset[v + 1];
  for (int v = 0; v < nv; ++v) offset[v + 1] += offset[v];
  around.resize(offset[nv]);
  std::vector<int> fill(offset.begin(), offset.end() - 1);
  for (std::size_t k = 0; k < tris.size(); ++k) around[fill[tris[k]]++] = static_cast<int>(k / 3);
  for (int ring = 0; ring < rings; ++ring) {
    const std::size_t n = set.size();
    for (std::size_t i = 0; i < n; ++i)
      for (int a = offset[set[i]]; a < offset[set[i] + 1]; ++a)
        for (int k = 0; k < 3; ++k) set.push_back(tris[3 * around[a] + k]);
  }
  std::sort(set.begin(), set.end());
  set.erase(std::unique(set.begin(), set.end()), set.end());
  return set;
}

long restore_vertices_to_input(TetMesh& mesh, const TetMesh& input, const VertexTets& star,
                               const std::vector<int>& vertices) {
  long n = 0;
  const int n_in = std::min(mesh.nb_vertices(), input.nb_vertices());
  for (int v : vertices) {
    if (v >= n_in) continue;
    const double* home = input.point(v);
    double* p = mesh.point(v);
    if (p[0] == home[0] && p[1] == home[1] && p[2] == home[2]) continue;
    const std::array<double, 3> old{p[0], p[1], p[2]};
    std::copy(home, home + 3, p);
    bool positive = true;
    for (const int* t = star.begin_of(v); t != star.end_of(v) && positive; ++t) {
      const int* tv = &mesh.tets[4 * static_cast<std::size_t>(*t)];
      positive =
          orient3d(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]), mesh.point(tv[3])) > 0;
    }
    if (positive)
      ++n;
    else
      std::copy(old.begin(), old.end(), p);
  }
  return n;
}

}  // namespace cvtmesh
