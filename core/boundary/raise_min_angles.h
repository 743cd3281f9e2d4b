// Raising the smallest dihedral angles within the mesh's other extremes (issue 17's last quality
// rows). The repairs before it rank a tet by min(Q, min dihedral angle / 60 degrees): where the
// tet of the smallest angle is also the tet of Q_min (Gmsh t18 after the free boundary: a needle
// triangle of the surface at a CAD corner, its tet Q 0.032 and 6.03 degrees), they work on its Q
// and stop where Q cannot rise, though its angle could, at the same Q, with a surface vertex and
// an interior vertex moved together. For each tet whose smallest dihedral angle is below `target`,
// lowest first, each of its vertices is moved in turn by the pattern search of pattern_move.h
// (interior vertices in space, surface vertices on their surface, curve vertices along their
// curve) on its star's minimum of min(dihedral angle, target): a tet above the target may come
// down to it, none below it falls. A position is taken only if every tet of the mover's star stays
// within absolute bounds: Q at least q_floor, dihedral angles at most max(angle_ceiling, the tet's
// maximum before), element time step at least dt_floor (the caller passes the mesh's minima: then
// Q_min does not fall, and a ceiling at most the mesh's maximum: then the maximum does not rise),
// the star's sum of Q at least its sum before (so the mesh's average Q never falls), and for a
// boundary vertex the checks of every boundary move (orientation, folds, Hausdorff, volume
// budget). Connectivity never changes; corners, locked and pinned vertices never move.
// Serial, in a fixed order.
#pragma once

#include "core/boundary/pattern_move.h"
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct AngleRaiseOptions {
  double target = 0;  // degrees: the tets whose smallest dihedral angle is below it are raised
  // The bounds every tet of a mover's star keeps (above).
  double q_floor = 0, angle_ceiling = 180, dt_floor = 0;
  int max_tets = 32;  // low tets tried at most per pass (the lowest first)
  int passes = 3;     // passes over the low tets (stops when nothing moves)
  // Each mover's search (pattern_move.h): the Hausdorff bound, the volume budget, its steps and
  // evaluations; its stop_at is set here (the target).
  PatternMoveOptions search;
};

struct AngleRaiseStats {
  long nb_low = 0;                       // tets below the target at the start
  long nb_moved = 0;                     // moves kept
  double min_before = 0, min_after = 0;  // the smallest dihedral angle of the mesh (degrees)
};

// Dead tets (tets[4t] < 0) are ignored; mesh.adj is not needed. model without geometry: only
// interior vertices move.
AngleRaiseStats raise_min_angles(TetMesh& mesh, const BoundaryModel& model,
                                 const AngleRaiseOptions& options = {});

}  // namespace cvtmesh
