// The check after every iteration of the 3D Lloyd loop (lloyd3.h).
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// The mesh after an iteration: full -> check_mesh (orientation, adjacency, closed boundary,
// constrained triangles present, interfaces); otherwise every live tet's orientation (exact
// orient3d, in parallel: the moves and flips change connectivity only through apply_swap, whose
// structure the full check verifies every few iterations and at the end). Then every interior
// vertex still has tets. Throws InvariantError.
void verify_lloyd3_mesh(const TetMesh& mesh, bool full);

}  // namespace cvtmesh
