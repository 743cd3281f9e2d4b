#include "core/swap/edge_ring.h"

#include <stdexcept>
#include <string>

#include "core/util/error.h"

namespace cvtmesh {
namespace {

// Parity of the permutation (i, j, k, l) of (0, 1, 2, 3): true if even.
bool even_permutation(int i, int j, int k, int l) {
  const int p[4] = {i, j, k, l};
  int inversions = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      if (p[a] > p[b]) ++inversions;
  return inversions % 2 == 0;
}

int local_index(const int* tv, int v) {
  for (int k = 0; k < 4; ++k)
    if (tv[k] == v) return k;
  throw InvariantError("edge ring: vertex " + std::to_string(v) + " is not in the tet");
}

}  // namespace

EdgeRing edge_ring(const TetMesh& mesh, int t, int e, int max_size) {
  if (t < 0 || t >= mesh.nb_tets() || mesh.tets[4 * static_cast<std::size_t>(t)] < 0)
    throw std::invalid_argument("edge_ring: tet " + std::to_string(t) + " is not a live tet");
  if (e < 0 || e > 5) throw std::invalid_argument("edge_ring: edge index must be 0..5");
  const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
  const int i = kTetEdge[e][0], j = kTetEdge[e][1];
  int k = -1, l = -1;
  for (int m = 0; m < 4; ++m)
    if (m != i && m != j) (k < 0 ? k : l) = m;
  // (p, q, r0, r1) must be an even permutation of the (positive) tet.
  if (!even_permutation(i, j, k, l)) std::swap(k, l);
  EdgeRing r;
  r.p = tv[i];
  r.q = tv[j];
  r.ring = {tv[k], tv[l]};
  r.tets = {t};
  int cur = t;
  while (true) {
    // The next tet shares the face (p, q, r_last) with the current one: the face opposite
    // r_{last-1}. Its vertex opposite that face is the next ring vertex.
    const int* cv = &mesh.tets[4 * static_cast<std::size_t>(cur)];
    const int prev = r.ring[r.ring.size() - 2];
    const int slot = mesh.adj[4 * static_cast<std::size_t>(cur) + local_index(cv, prev)];
    if (slot < 0) {
      r.on_boundary = true;
      return r;
    }
    const int next = slot / 4;
    const int v = mesh.tets[static_cast<std::size_t>(slot)];
    if (next == t) throw InvariantError("edge ring: adjacency loops back without closing");
    if (static_cast<int>(r.tets.size()) >= max_size) return r;  // too large
    r.tets.push_back(next);
    if (v == r.ring[0]) {
      r.closed = true;
      return r;
    }
    r.ring.push_back(v);
    cur = next;
  }
}

}  // namespace cvtmesh
