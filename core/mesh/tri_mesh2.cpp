#include "core/mesh/tri_mesh2.h"

#include <algorithm>
#include <string>

#include "core/util/error.h"

namespace cvtmesh {

void build_adjacency2(TriMesh2& mesh) {
  const int nt = mesh.nb_tris();
  mesh.adj.assign(3 * static_cast<std::size_t>(nt), -1);
  struct Rec {
    int a, b, slot;
  };
  std::vector<Rec> recs;
  recs.reserve(3 * static_cast<std::size_t>(nt));
  for (int t = 0; t < nt; ++t) {
    const int* tv = &mesh.tris[3 * static_cast<std::size_t>(t)];
    if (tv[0] < 0) continue;
    for (int e = 0; e < 3; ++e) {
      int a = tv[(e + 1) % 3], b = tv[(e + 2) % 3];
      if (a > b) std::swap(a, b);
      recs.push_back({a, b, 3 * t + e});
    }
  }
  std::sort(recs.begin(), recs.end(), [](const Rec& x, const Rec& y) {
    if (x.a != y.a) return x.a < y.a;
    if (x.b != y.b) return x.b < y.b;
    return x.slot < y.slot;
  });
  for (std::size_t i = 0; i < recs.size();) {
    std::size_t j = i + 1;
    while (j < recs.size() && recs[j].a == recs[i].a && recs[j].b == recs[i].b) ++j;
    if (j - i > 2)
      throw InputError("non-manifold triangle mesh: edge (" + std::to_string(recs[i].a) + ", " +
                       std::to_string(recs[i].b) + ") is shared by " + std::to_string(j - i) +
                       " triangles");
    if (j - i == 2) {
      mesh.adj[recs[i].slot] = recs[i + 1].slot;
      mesh.adj[recs[i + 1].slot] = recs[i].slot;
    }
    i = j;
  }
}

}  // namespace cvtmesh
