// The ring of tets around an edge, found by walking the adjacency (no O(#T) work).
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct EdgeRing {
  int p = -1, q = -1;  // the edge's end points
  // r_0..r_{n-1}, counter-clockwise around the directed edge p->q:
  // tet i of the ring is (p, q, r_i, r_{i+1 mod n}) and orient3d(p, q, r_i, r_{i+1}) > 0.
  std::vector<int> ring;
  // tets[i] = the tet id holding p, q, r_i, r_{i+1 mod n}.
  std::vector<int> tets;
  bool closed = false;       // the walk came back to the first tet
  bool on_boundary = false;  // the walk met a face with no tet behind it (a boundary edge)
};

// Walks around edge e (local index into kTetEdge) of the live tet t; stops after max_size tets
// (then closed = on_boundary = false: the ring is larger than max_size). Needs mesh.adj.
// Throws std::invalid_argument for a dead tet or an edge index outside 0..5.
EdgeRing edge_ring(const TetMesh& mesh, int t, int e, int max_size);

}  // namespace cvtmesh
