// Re-insertion of the moved vertices in the 3D Lloyd iteration (lloyd3.h: local_flips,
// max_flip_leftover): the vertices follow their targets by exact Lawson flips on the current
// mesh (relocate_vertices3.h), or the constrained Delaunay mesh of the targets is rebuilt by the
// backend when the flips leave too many vertices short of their targets (or are off).
#pragma once
#include <vector>

#include "core/cvt/lloyd.h"
#include "core/delaunay/delaunay3.h"
#include "core/mesh/face_key.h"
#include "core/mesh/tet_mesh.h"
#include "core/swap/constrained_faces.h"

namespace cvtmesh {

struct Reinsertion {
  bool delaunay = false;  // every unconstrained face is locally Delaunay
  // The flips restored the mesh: every unconstrained face not in non_delaunay_faces is locally
  // Delaunay (false after a rebuild: TetGen's mesh is not tested).
  bool faces_listed = false;
  std::vector<FaceKey> non_delaunay_faces;
  int nb_steiner = 0;  // added by a rebuild
};

// Moves the vertices of `mesh` to `target` (3*#V). Fills s.nb_flips, s.nb_stuck_faces,
// s.nb_short_moves and s.rebuilt.
Reinsertion reinsert_vertices3(TetMesh& mesh, const ConstrainedFaces& constrained,
                               const std::vector<double>& target, bool local_flips,
                               double max_flip_leftover, Delaunay3& backend, LloydStep& s);

}  // namespace cvtmesh
