#include "core/mesh/build_adjacency.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/util/error.h"

namespace cvtmesh {

void build_adjacency(TetMesh& mesh) {
  const int nt = mesh.nb_tets();
  mesh.adj.assign(4 * static_cast<std::size_t>(nt), -1);
  // Sort (sorted face, 4t+f) records; equal faces become neighbours. O(T log T), no hashing.
  struct Rec {
    int a, b, c, slot;
  };
  std::vector<Rec> recs;
  recs.reserve(4 * static_cast<std::size_t>(nt));
  for (int t = 0; t < nt; ++t) {
    const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
    if (tv[0] < 0) continue;
    for (int f = 0; f < 4; ++f) {
      int v[3] = {tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]]};
      std::sort(v, v + 3);
      recs.push_back({v[0], v[1], v[2], 4 * t + f});
    }
  }
  std::sort(recs.begin(), recs.end(), [](const Rec& x, const Rec& y) {
    if (x.a != y.a) return x.a < y.a;
    if (x.b != y.b) return x.b < y.b;
    if (x.c != y.c) return x.c < y.c;
    return x.slot < y.slot;
  });
  for (std::size_t i = 0; i < recs.size();) {
    std::size_t j = i + 1;
    while (j < recs.size() && recs[j].a == recs[i].a && recs[j].b == recs[i].b &&
           recs[j].c == recs[i].c)
      ++j;
    if (j - i > 2)
      throw InputError("non-manifold volume mesh: a triangle (vertices " +
                       std::to_string(recs[i].a) + ", " + std::to_string(recs[i].b) + ", " +
                       std::to_string(recs[i].c) + ") is shared by " + std::to_string(j - i) +
                       " tetrahedra");
    if (j - i == 2) {
      mesh.adj[recs[i].slot] = recs[i + 1].slot;
      mesh.adj[recs[i + 1].slot] = recs[i].slot;
    }
    i = j;
  }
}

}  // namespace cvtmesh
