// Folds of the boundary surface: the turn of the normal across an edge of two boundary
// triangles. A boundary vertex move or a surface flip must not fold the surface (igl_bunny: the
// constrained CVT turned a triangle over, leaving two triangles whose normals were 171 degrees
// apart and a cap tet of Q 0.02 between them, with every tet positive and the Hausdorff bound
// kept). The rule, after MMG's normal-deviation checks of its boundary moves: no edge of the
// changed triangles (and of their neighbours across their edges) may end sharper than
// min(before, kFoldFloor); where the surface was already sharper (a feature) it may not get
// sharper.
#pragma once
#include <array>

#include "core/boundary/boundary_fans.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// cos of the sharpest turn a change may create where there was none: about 154 degrees. A
// surface triangle turned over turns by nearly 180 degrees; a model's own sharp edges are
// shallower (t13's sharpest, 138 degrees, stays free to move: with 120 degrees here its Q_min fell
// from 0.3407 to 0.2870, igl_bunny and igl_screwdriver gaining the same either way).
constexpr double kFoldFloor = -0.9;

// cos of the turn across edge (p, q) between boundary triangles f and g (g's normal reversed if
// it runs p -> q the same way as f: consistently oriented or not); 0 if one is degenerate.
double cos_turn(const TetMesh& mesh, int f, int g, int p, int q);

// The two triangles {a, c, d} and {b, d, c} that replace f1 = {a, b, c} and f2 = {a, b, d} when
// surface edge (a, b) flips to (c, d), as vertex triples turning as the old ones did.
std::array<int, 6> flipped_triangles(const TetMesh& mesh, int f1, int a, int b, int c, int d);

// Writes flipped_triangles into f1 and f2 (the edge flip and the cap removal).
void retarget_flipped_triangles(TetMesh& mesh, int f1, int f2, int a, int b, int c, int d);

// Whether moving boundary vertex v to `position` folds the surface: some edge of v's fan
// triangles ends with cos(turn) below min(cos before, floor). `fans` current for the mesh.
bool move_folds_surface(const TetMesh& mesh, const BoundaryFans& fans, int v,
                        const double* position, double floor = kFoldFloor);

// Whether flipping surface edge (a, b) to (c, d) folds the surface: the new pair turns by more
// than acos(pair_floor) across (c, d), or an outer edge ((a, c), (c, b), (b, d), (d, a)) ends
// below min(before, floor).
bool flip_folds_surface(const TetMesh& mesh, const BoundaryFans& fans, int f1, int f2, int a, int b,
                        int c, int d, double pair_floor, double floor = kFoldFloor);

}  // namespace cvtmesh
