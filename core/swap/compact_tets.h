// Removes the dead tet slots (tets[4t] < 0) left by local operations, keeping the order of the
// live tets, and rebuilds the adjacency by renumbering it (O(#T)).
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// Keeps tet_region and tet_tags (when not empty) in step. Returns the number of slots removed.
// If mesh.adj is not 4*#T (not built), it is built from scratch (build_adjacency).
int compact_tets(TetMesh& mesh);

}  // namespace cvtmesh
