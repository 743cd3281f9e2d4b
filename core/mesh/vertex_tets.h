// Vertex -> tets incidence of a tet mesh, in compressed (CSR) form.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct VertexTets {
  // #V+1 offsets: the tets around vertex v are tets[offset[v] .. offset[v+1]-1].
  std::vector<int> offset;
  // Live tet ids (0-based), grouped by vertex, increasing within a vertex.
  std::vector<int> tets;

  int nb_tets_of(int v) const { return offset[v + 1] - offset[v]; }
  const int* begin_of(int v) const { return tets.data() + offset[v]; }
  const int* end_of(int v) const { return tets.data() + offset[v + 1]; }
};

// The star of every vertex: the live tets (tets[4t] >= 0) incident to it. O(#V + #T).
// Stays valid while only coordinates change; rebuild it after a change of connectivity.
VertexTets vertex_tets(const TetMesh& mesh);
// The same into `out`, reusing its arrays (the Lloyd iteration rebuilds the stars every
// iteration: at 10M tets ~170 MB, paged in afresh each time otherwise).
void vertex_tets(const TetMesh& mesh, VertexTets& out);

// The stars of `vertices` only (the other vertices' are empty): one pass over the tets, for a few
// vertices of a large mesh.
VertexTets vertex_tets_of(const TetMesh& mesh, const std::vector<int>& vertices);

// The length of the shortest edge from v to the other vertices of the tets [b, e) (v's star, as
// VertexTets or VertexStar list it); +inf for an empty star. The smoothings scale their steps by
// it.
double shortest_star_edge(const TetMesh& mesh, const int* b, const int* e, int v);

}  // namespace cvtmesh
