#include "core/delaunay/cdt2d_remesh.h"

#include <string>
#include <vector>

#include "core/delaunay/cdt2d.h"
#include "core/mesh/edge_index.h"
#include "core/util/error.h"

namespace cvtmesh {

void cdt2d_remesh(TriMesh2& mesh, Cdt2dResult* delaunay) {
  if (delaunay) *delaunay = Cdt2dResult();
  // Surface on the left of each directed constrained edge (u -> v counter-clockwise in a
  // triangle): left[2 e] for edges[2 e] -> edges[2 e + 1], left[2 e + 1] the other way, e the
  // first of the edges {u, v} (cons.find); -1 where no triangle is on that side.
  const EdgeIndex cons(mesh.edges, mesh.nb_vertices());
  std::vector<int> left(mesh.edges.size(), -1);
  for (int t = 0; t < mesh.nb_tris(); ++t) {
    const int* tv = &mesh.tris[3 * t];
    if (tv[0] < 0) continue;
    for (int k = 0; k < 3; ++k) {
      const int u = tv[k], v = tv[(k + 1) % 3];
      const int e = cons.find(u, v);
      if (e >= 0) left[2 * e + (mesh.edges[2 * e] == u ? 0 : 1)] = mesh.tri_region[t];
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
  Cdt2dResult r;
  if (!all)
    r = cdt2d(sub_xy, sub_edges);
  else if (delaunay)
    cdt2d_and_delaunay(mesh.xy, mesh.edges, r, *delaunay);
  else
    r = cdt2d(mesh.xy, mesh.edges);
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
  const EdgeIndex is_seg(r.segments, static_cast<int>(r.xy.size() / 2) + (all ? 0 : nv));
  for (int t = 0; t < nt; ++t) {
    const int c = r.component[t];
    if (c < 0) continue;
    for (int k = 0; k < 3; ++k) {
      const int u = r.tris[3 * t + k], v = r.tris[3 * t + (k + 1) % 3];
      if (!is_seg.contains(u, v)) continue;
      const int e = cons.find(u, v);  // r.segments are mesh.edges (no split: checked above)
      const int reg = e < 0 ? -1 : left[2 * e + (mesh.edges[2 * e] == u ? 0 : 1)];
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
