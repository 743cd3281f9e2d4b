#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// Fills mesh.adj (4*#T, packed adj[4t+f] = 4t'+f', -1 on the boundary) from mesh.tets.
// Dead tets (tets[4t] < 0) get -1 everywhere. Throws InputError if a face is shared by more than
// two tets (non-manifold volume mesh).
void build_adjacency(TetMesh& mesh);

}  // namespace cvtmesh
