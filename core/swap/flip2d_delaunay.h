// Delaunay acceptance test of the 2D edge flip (flip2d.h).
#pragma once
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// True if the edge at packed slot `slot` = 3t+e is locally Delaunay: it is on the boundary, or
// the apex of the neighbouring triangle is not strictly inside the circumcircle of t (exact
// incircle). Cocircular configurations count as Delaunay, so a flip pass terminates.
bool is_locally_delaunay2d(const TriMesh2& mesh, int slot);

}  // namespace cvtmesh
