// Restores the constrained Delaunay property of a tet mesh after its free vertices moved a little,
// by Lawson flips (2-3 across a face whose opposite vertex lies inside the circumsphere, 3-2 around
// the reflex edge of degree three), decided by exact predicates. Much cheaper than rebuilding the
// tetrahedralization when few faces changed. Constrained faces are never flipped.
#pragma once
#include <vector>

#include "core/mesh/face_key.h"
#include "core/mesh/tet_mesh.h"
#include "core/swap/constrained_faces.h"

namespace cvtmesh {

struct RestoreDelaunayStats {
  bool ok = false;        // every unconstrained face is locally Delaunay on exit
  bool inverted = false;  // a tet was inverted or flat on entry: nothing was done
  int nb_flips23 = 0, nb_flips32 = 0;
  int nb_stuck = 0;  // non-Delaunay faces no flip could remove (ok = false)
  // Those faces (sorted vertex ids): every unconstrained face of the mesh on exit that the call
  // may have left non-Delaunay (the faces it tested or created and could not flip) is here.
  std::vector<FaceKey> stuck_faces;
};

// `mesh` must have its adjacency built; on entry its connectivity is that of a valid mesh of the
// domain and only coordinates of free vertices changed. If some tet is not positively oriented
// (exact orient3d) nothing changes and `inverted` is set. Otherwise flips until no unconstrained
// face is non-locally-Delaunay or none of the remaining can be flipped (stuck); dead slots are
// compacted on exit. The mesh stays valid (positively oriented, same constrained triangles and
// region volumes) whether or not `ok`.
// check_orientation = false: the caller guarantees that every tet is positively oriented.
RestoreDelaunayStats restore_delaunay_by_flips(TetMesh& mesh, const ConstrainedFaces& constrained,
                                               bool check_orientation = true);

// The same, when only the tets `tets` (live ids of the current mesh; e.g. the stars of the
// vertices that moved since the mesh was valid and constrained Delaunay) can have non-Delaunay
// faces: only their faces are tested at first (then whatever the flips touch), and the
// orientation check is left to the caller (each move kept its star positively oriented).
RestoreDelaunayStats restore_delaunay_in(TetMesh& mesh, const ConstrainedFaces& constrained,
                                         const std::vector<int>& tets);

}  // namespace cvtmesh
