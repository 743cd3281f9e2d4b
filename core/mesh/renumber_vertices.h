// Vertex renumbering: after a round trip through another tool (Gmsh), put the vertices back in
// the order of a reference mesh, matching them by node tag.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// Applies the permutation new_id[old] to every array of the mesh (xyz, vclass, node_tags, tets,
// tris, extra element blocks). new_id must be a permutation of 0..#V-1. The tet adjacency is kept
// (built if it was not).
void permute_vertices(TetMesh& mesh, const std::vector<int>& new_id);

// Renumbers `mesh` so that a vertex with the same node tag as vertex i of `ref` gets index i;
// vertices with other tags follow in their current order. No-op without node tags.
void renumber_vertices_like(TetMesh& mesh, const TetMesh& ref);

}  // namespace cvtmesh
