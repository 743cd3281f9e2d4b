// Re-triangulates a planar mesh in place: the constrained Delaunay triangulation of its current
// vertex positions, with its constrained edges (boundary and interfaces) and surfaces kept.
#pragma once
#include "core/delaunay/cdt2d.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// Replaces mesh.tris, tri_region and adj by the constrained Delaunay triangulation (cdt2d) of
// mesh.xy with the segments mesh.edges. Each side of each constrained edge keeps the surface it
// had in the current mesh.tris (or stays outside: holes are kept). Vertices, edges and their
// classification are unchanged; tri_tags is cleared (the triangles are new).
// The current mesh only needs correct connectivity next to its constrained edges: the vertices
// may have moved. Throws InputError if a vertex lies on a constrained edge or the two sides of
// one enclosed part disagree (a vertex crossed a constrained edge), and whatever cdt2d throws.
// delaunay: if given, receives cdt2d(mesh.xy, {}) (the unconstrained Delaunay triangulation of
// the new positions, from the same point insertion) when every vertex is in a triangle or on a
// constrained edge; otherwise it is left empty (no triangles).
void cdt2d_remesh(TriMesh2& mesh, Cdt2dResult* delaunay = nullptr);

}  // namespace cvtmesh
