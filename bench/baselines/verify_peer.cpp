#include "bench/baselines/verify_peer.h"

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "core/mesh/build_adjacency.h"
#include "core/mesh/check_mesh.h"
#include "core/util/error.h"

namespace cvtmesh {

namespace {

using Point = std::array<double, 3>;
using Triangle = std::pair<std::array<Point, 3>, int>;

std::vector<Triangle> boundary_triangles(const TetMesh& m) {
  std::vector<Triangle> out;
  out.reserve(m.nb_tris());
  for (int f = 0; f < m.nb_tris(); ++f) {
    std::array<Point, 3> p;
    for (int k = 0; k < 3; ++k) {
      const double* x = m.point(m.tris[3 * f + k]);
      p[k] = {x[0], x[1], x[2]};
    }
    std::sort(p.begin(), p.end());
    out.push_back({p, m.tri_surface[f]});
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

void verify_peer(const TetMesh& before, const TetMesh& after, const std::string& peer) {
  const MeshCheck c = check_mesh(after);
  if (!c.ok)
    throw InvariantError(peer + " returned an invalid mesh: " +
                         (c.problems.empty() ? std::string("?") : c.problems.front()));
  if (boundary_triangles(before) != boundary_triangles(after))
    throw InvariantError(peer + " changed the boundary triangles (" +
                         std::to_string(before.nb_tris()) + " -> " +
                         std::to_string(after.nb_tris()) + ")");
}

void classify_peer_vertices(const TetMesh& before, TetMesh& after) {
  std::map<Point, int> at;
  for (int v = 0; v < before.nb_vertices(); ++v) {
    const double* x = before.point(v);
    at[{x[0], x[1], x[2]}] = v;
  }
  const int n = after.nb_vertices();
  after.vclass.assign(n, VertexClass{3, 0});
  after.node_tags.assign(n, 0);
  std::vector<char> known(n, 0);
  for (int v = 0; v < n; ++v) {
    const double* x = after.point(v);
    const auto it = at.find({x[0], x[1], x[2]});
    if (it == at.end()) continue;
    known[v] = 1;
    after.vclass[v] = before.vclass[it->second];
    if (!before.node_tags.empty()) after.node_tags[v] = before.node_tags[it->second];
  }
  for (int t = 0; t < after.nb_tets(); ++t)
    for (int k = 0; k < 4; ++k) {
      const int v = after.tets[4 * t + k];
      if (!known[v]) after.vclass[v].entity = after.tet_region[t];
    }
  after.model = before.model;
  build_adjacency(after);
}

}  // namespace cvtmesh
