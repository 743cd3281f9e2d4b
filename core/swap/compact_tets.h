// Removes the dead tet slots (tets[4t] < 0) left by local operations, keeping the order of the
// live tets, and rebuilds the adjacency by renumbering it (O(#T)).
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// Keeps tet_region and tet_tags (when not empty) in step. Returns the number of slots removed.
// If mesh.adj is not 4*#T (not built), it is built from scratch (build_adjacency).
int compact_tets(TetMesh& mesh);

// The same without keeping the order: each dead slot below the new end takes a live tet from the
// end (its neighbours' links follow). O(#dead slots + the tail) instead of O(#T): for a large mesh
// with a few holes (adjacency must be built). Returns the number of slots removed.
int compact_tets_fill(TetMesh& mesh);

}  // namespace cvtmesh
