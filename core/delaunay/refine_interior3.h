// Interior refinement before Lloyd: the constrained Delaunay tetrahedralization of the current
// vertices rebuilt by TetGen with its quality bound (-q: Steiner points at the circumcentres of
// the tets whose circumradius exceeds radius_edge times their shortest edge), the boundary mesh
// kept (-Y: the points are interior only). On a model whose Init has too few interior vertices
// for its surface (igl_decimated-knight: 1425 tets, the average Q of our default stuck at 0.60
// where Netgen and CGAL, which add vertices, reach 0.64) the points the CVT then spreads are what
// the mesh lacked; on a well-graded Init few are added (cube_sphere 25k: 33 at 1.2).
#pragma once
#include "core/delaunay/delaunay3.h"

namespace cvtmesh {

// radius_edge > 1 (TetGen's bound; 1.2 to 2 in practice). The new vertices are appended,
// interior (class 3, the region of one of their tets); the tets are rebuilt (the constrained
// Delaunay tetrahedralization: the mesh's connectivity changes even where nothing is added).
// Throws InvariantError as the Delaunay rebuild does.
Delaunay3Stats refine_interior3(TetMesh& mesh, double radius_edge);

}  // namespace cvtmesh
