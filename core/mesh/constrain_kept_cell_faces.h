// Hybrid meshes: the boundary faces of the tets that no surface triangle covers where they touch
// a kept non-tet cell (prism, pyramid, hexahedron in mesh.model.extra, in the same volume) become
// constrained triangles of a marked, not-written surface (kKeptCellInterface: tri_surface =
// -1 - the tet's region), so that every operation keeps them exactly. The .msh writer skips
// them.
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// True for the surface tag of such an interface triangle.
inline bool is_kept_cell_interface(int surface_tag) {
  return surface_tag < 0;
}

// Requires the adjacency. Returns the number of triangles added (0 without kept 3D cells).
int constrain_kept_cell_faces(TetMesh& mesh);

}  // namespace cvtmesh
