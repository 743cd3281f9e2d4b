// 2D hybrid meshes: the boundary edges of the triangles that no line covers where they touch a
// kept quadrangle (mesh.model.extra; in the same surface, or one whose common curve has no line)
// become constrained edges of a marked, not-written curve (edge_curve = -1 - the triangle's
// surface: is_kept_cell_interface, constrain_kept_cell_faces.h), so that every operation keeps
// them exactly and no triangle ever overlaps a quadrangle. The .msh writer skips them.
#pragma once
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// Requires the adjacency. Returns the number of edges added (0 without kept quadrangles).
int constrain_kept_quad_edges(TriMesh2& mesh);

}  // namespace cvtmesh
