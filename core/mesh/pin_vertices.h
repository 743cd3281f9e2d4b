// Vertices that must not move although the optimizer would treat them as free: those of the
// elements kept verbatim in mesh.model.extra (hybrid cells, quadrangles, loose triangles; lines
// and points only off the boundary triangles) and the nodes of periodic links (mesh.model.periodic,
// by node tag). pin_vertices classifies them as corners with a marked entity (dim 0, entity < 0,
// encoding the original class) for the duration of an optimization; unpin_vertices restores
// their classification (after any vertex permutation: the mark travels with the vertex).
#pragma once
#include "core/mesh/tet_mesh.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// Returns the number of vertices pinned.
int pin_vertices(TetMesh& mesh);
void unpin_vertices(TetMesh& mesh);

// The same for a planar mesh: the vertices of its kept quadrangles, and those of its kept lines
// and points that are on no constrained edge (a free curve's; keep_free_curve_lines.h).
int pin_vertices(TriMesh2& mesh);
void unpin_vertices(TriMesh2& mesh);

}  // namespace cvtmesh
