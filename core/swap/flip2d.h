// The 2D edge flip: one operator that only edits connectivity. Whether a flip is wanted is
// decided elsewhere (flip2d_delaunay.h, flip2d_quality.h); flip2d_pass.h combines them.
#pragma once
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// Flips the edge at packed slot `slot` = 3t+e of mesh (edge e of triangle t, opposite its vertex
// e) when the quadrilateral of the two triangles sharing it is strictly convex (exact orient2d),
// so that both new triangles are counter-clockwise. With t = (c,a,b) and its neighbour
// t2 = (d,b,a) (c, d the apices), the result is t = (c,a,d) and t2 = (d,b,c): the new edge (c,d)
// is slot 3t+1 (paired with 3t2+1), the four outer edges are slots 3t, 3t+2, 3t2, 3t2+2.
// mesh.adj must be built; it is kept consistent. tri_region is left as is (both triangles are
// expected to be in the same surface). Returns false, and leaves the mesh untouched, if the
// edge is on the boundary (no neighbour) or the quadrilateral is not strictly convex.
// The caller is responsible for never flipping a constrained edge (mesh.edges).
bool flip2d(TriMesh2& mesh, int slot);

// True if flip2d(mesh, slot) would succeed (neighbour present, strictly convex quadrilateral).
bool flip2d_possible(const TriMesh2& mesh, int slot);

}  // namespace cvtmesh
