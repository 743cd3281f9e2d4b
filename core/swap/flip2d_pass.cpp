#include "core/swap/flip2d_pass.h"

#include <vector>

#include "core/mesh/edge_index.h"
#include "core/swap/flip2d.h"
#include "core/swap/flip2d_delaunay.h"
#include "core/swap/flip2d_no_worse.h"
#include "core/swap/flip2d_quality.h"

namespace cvtmesh {

long flip2d_pass(TriMesh2& mesh, const Flip2dPassOptions& options) {
  const EdgeIndex constrained(mesh.edges, mesh.nb_vertices());
  const int nt = mesh.nb_tris();
  const long cap = options.max_flips > 0 ? options.max_flips : 100L * nt + 100;
  const bool has_region = static_cast<int>(mesh.tri_region.size()) == nt;

  std::vector<int> stack;
  stack.reserve(3 * static_cast<std::size_t>(nt));
  for (int t = nt - 1; t >= 0; --t)
    if (mesh.tris[3 * t] >= 0)
      for (int e = 2; e >= 0; --e) stack.push_back(3 * t + e);

  long flips = 0;
  while (!stack.empty() && flips < cap) {
    const int slot = stack.back();
    stack.pop_back();
    const int o = mesh.adj[slot];
    if (o < 0 || slot > o) continue;  // boundary, or examined from the other side
    const int t = slot / 3, e = slot % 3, t2 = o / 3;
    const int* tv = &mesh.tris[3 * t];
    if (constrained.contains(tv[(e + 1) % 3], tv[(e + 2) % 3])) continue;
    if (has_region && mesh.tri_region[t] != mesh.tri_region[t2]) continue;
    const bool wanted = options.criterion == FlipCriterion2d::kDelaunay
                            ? !is_locally_delaunay2d(mesh, slot)
                        : options.criterion == FlipCriterion2d::kNoWorse
                            ? flip2d_no_worse(mesh, slot)
                            : flip2d_improves_quality(mesh, slot, options.measure);
    if (!wanted || !flip2d(mesh, slot)) continue;
    ++flips;
    for (int s : {3 * t, 3 * t + 2, 3 * t2, 3 * t2 + 2}) {
      stack.push_back(s);
      if (mesh.adj[s] >= 0) stack.push_back(mesh.adj[s]);
    }
  }
  return flips;
}

}  // namespace cvtmesh
