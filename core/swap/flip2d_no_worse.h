// The never-worse acceptance test of the 2D edge flip (flip2d.h): a flip that no quality row of
// the mesh can see as a loss.
#pragma once
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// True if flipping the edge at packed slot `slot` = 3t+e is possible (flip2d_possible) and, over
// the two triangles, the minimum Q and the minimum angle do not fall, the maximum angle does not
// rise, and the minimum Q or the sum of Q rises (by more than 1e-9 / 1e-12 relative). So the
// mesh's minimum and average Q, minimum and maximum angle are never worse after it. The caller
// keeps constrained edges out (mesh.edges).
bool flip2d_no_worse(const TriMesh2& mesh, int slot);

}  // namespace cvtmesh
