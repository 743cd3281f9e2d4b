#include "core/mesh/build_adjacency.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/util/error.h"

namespace cvtmesh {

void build_adjacency(TetMesh& mesh) {
  const int nt = mesh.nb_tets(), nv = mesh.nb_vertices();
  mesh.adj.assign(4 * static_cast<std::size_t>(nt), -1);
  // (sorted face, 4t+f) records bucketed by the face's smallest vertex (a counting sort), each
  // bucket sorted by the other two and the slot: equal faces become neighbours. O(T) plus small
  // sorts, no hashing; the buckets in parallel.
  struct Rec {
    int b, c, slot;
  };
  std::vector<int> start(static_cast<std::size_t>(nv) + 1, 0);
  for (int t = 0; t < nt; ++t) {
    const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
    if (tv[0] < 0) continue;
    for (int f = 0; f < 4; ++f)
      ++start[std::min({tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]]}) + 1];
  }
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<Rec> recs(static_cast<std::size_t>(start[nv]));
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < nt; ++t) {
      const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
      if (tv[0] < 0) continue;
      for (int f = 0; f < 4; ++f) {
        int v[3] = {tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]]};
        std::sort(v, v + 3);
        recs[fill[v[0]]++] = {v[1], v[2], 4 * t + f};
      }
    }
  }
  // The first bucket holding a face of more than two tets (nv if none).
  int bad = nv;
#pragma omp parallel for schedule(dynamic, 4096) reduction(min : bad)
  for (int a = 0; a < nv; ++a) {
    Rec* first = recs.data() + start[a];
    Rec* last = recs.data() + start[a + 1];
    std::sort(first, last, [](const Rec& x, const Rec& y) {
      if (x.b != y.b) return x.b < y.b;
      if (x.c != y.c) return x.c < y.c;
      return x.slot < y.slot;
    });
    for (Rec* i = first; i < last;) {
      Rec* j = i + 1;
      while (j < last && j->b == i->b && j->c == i->c) ++j;
      if (j - i > 2) {
        bad = std::min(bad, a);
      } else if (j - i == 2) {
        mesh.adj[i->slot] = (i + 1)->slot;
        mesh.adj[(i + 1)->slot] = i->slot;
      }
      i = j;
    }
  }
  if (bad < nv) {
    const Rec* first = recs.data() + start[bad];
    const Rec* last = recs.data() + start[bad + 1];
    for (const Rec* i = first; i < last;) {
      const Rec* j = i + 1;
      while (j < last && j->b == i->b && j->c == i->c) ++j;
      if (j - i > 2)
        throw InputError("non-manifold volume mesh: a triangle (vertices " + std::to_string(bad) +
                         ", " + std::to_string(i->b) + ", " + std::to_string(i->c) +
                         ") is shared by " + std::to_string(j - i) + " tetrahedra");
      i = j;
    }
  }
}

}  // namespace cvtmesh
