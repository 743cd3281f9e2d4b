#include "core/delaunay/cdt2d_remesh.h"

#include <string>
#include <unordered_map>
#include <utility>

#include "core/delaunay/cdt2d.h"
#include "core/mesh/face_key.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

struct DirectedKeyHash {
  std::size_t operator()(const std::pair<int, int>& k) const {
    return EdgeKeyHash()(EdgeKey{k.first, k.second});
  }
};

}  // namespace

void cdt2d_remesh(TriMesh2& mesh) {
  // Surface on the left of each directed constrained edge (u -> v counter-clockwise in a triangle).
  std::unordered_map<std::pair<int, int>, int, DirectedKeyHash> left;
  {
    std::unordered_map<EdgeKey, int, EdgeKeyHash> cons;
    for (int e = 0; e < mesh.nb_edges(); ++e)
      cons[edge_key(mesh.edges[2 * e], mesh.edges[2 * e + 1])] = e;
    for (int t = 0; t < mesh.nb_tris(); ++t) {
      const int* tv = &mesh.tris[3 * t];
      if (tv[0] < 0) continue;
      for (int k = 0; k < 3; ++k) {
        const int u = tv[k], v = tv[(k + 1) % 3];
        if (cons.count(edge_key(u, v))) left[{u, v}] = mesh.tri_region[t];
      }
    }
  }
  // Only the vertices of the triangles and constrained edges: a hybrid or free-curve mesh's
  // vertices of no triangle (kept quadrangles', free curves') stay out of the triangulation.
  const int nv = mesh.nb_vertices();
  std::vector<int> local(static_cast<std::size_t>(nv), -1), global;
  auto use = [&](int v) {
    if (local[v] < 0) local[v] = static_cast<int>(global.size()), global.push_back(v);
  };
  for (int v : mesh.tris)
    if (v >= 0) use(v);
  for (int v : mesh.edges) use(v);
  const bool all = static_cast<int>(global.size()) == nv;
  std::vector<double> sub_xy;
  std::vector<int> sub_edges;
  if (!all) {
    sub_xy.reserve(2 * global.size());
    for (int v : global) sub_xy.insert(sub_xy.end(), mesh.point(v), mesh.point(v) + 2);
    sub_edges.reserve(mesh.edges.size());
    for (int v : mesh.edges) sub_edges.push_back(local[v]);
  }
  Cdt2dResult r = all ? cdt2d(mesh.xy, mesh.edges) : cdt2d(sub_xy, sub_edges);
  if (r.segments.size() != mesh.edges.size())
    throw InputError("cdt2d_remesh: a vertex lies on a constrained edge");
  if (!all) {
    // Back to the mesh's ids (the super-triangle's vertices are in no kept triangle).
    const int n = static_cast<int>(global.size());
    for (int& v : r.tris) v = v < n ? global[v] : nv + (v - n);
    for (int& v : r.segments) v = global[v];
  }

  // Surface of each enclosed part, from its constrained edges; -1 = hole.
  const int nt = static_cast<int>(r.tris.size() / 3);
  std::vector<int> part_region(r.nb_components, -2);
  std::unordered_map<EdgeKey, int, EdgeKeyHash> is_seg;
  for (std::size_t s = 0; 2 * s < r.segments.size(); ++s)
    is_seg[edge_key(r.segments[2 * s], r.segments[2 * s + 1])] = 1;
  for (int t = 0; t < nt; ++t) {
    const int c = r.component[t];
    if (c < 0) continue;
    for (int k = 0; k < 3; ++k) {
      const int u = r.tris[3 * t + k], v = r.tris[3 * t + (k + 1) % 3];
      if (!is_seg.count(edge_key(u, v))) continue;
      const auto it = left.find({u, v});
      const int reg = it == left.end() ? -1 : it->second;
      if (part_region[c] == -2) {
        part_region[c] = reg;
      } else if (part_region[c] != reg) {
        throw InputError(
            "cdt2d_remesh: the constrained edges around one part of the domain "
            "disagree on its surface (" +
            std::to_string(part_region[c]) + " vs " + std::to_string(reg) +
            "): a vertex crossed a constrained edge");
      }
    }
  }
  std::vector<int> new_id(nt, -1);
  int kept = 0;
  for (int t = 0; t < nt; ++t)
    if (r.component[t] >= 0 && part_region[r.component[t]] >= 0) new_id[t] = kept++;
  mesh.tris.assign(3 * static_cast<std::size_t>(kept), -1);
  mesh.tri_region.assign(kept, 0);
  mesh.adj.assign(3 * static_cast<std::size_t>(kept), -1);
  mesh.tri_tags.clear();
  for (int t = 0; t < nt; ++t) {
    const int n = new_id[t];
    if (n < 0) continue;
    mesh.tri_region[n] = part_region[r.component[t]];
    for (int k = 0; k < 3; ++k) {
      mesh.tris[3 * n + k] = r.tris[3 * t + k];
      const int o = r.adj[3 * t + k];
      if (o >= 0 && new_id[o / 3] >= 0) mesh.adj[3 * n + k] = 3 * new_id[o / 3] + o % 3;
    }
  }
}

}  // namespace cvtmesh
