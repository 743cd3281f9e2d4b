// Moves free vertices of a constrained Delaunay tet mesh to new positions and keeps the mesh
// constrained Delaunay without rebuilding it: each vertex moves as far towards its target as its
// star stays positively oriented (exact orient3d), then Lawson flips restore the Delaunay property
// (restore_delaunay3.h) and the vertices that did not reach their targets try again, for a few
// rounds. The Lloyd re-insertion step when the moves are small.
#pragma once
#include <vector>

#include "core/mesh/face_key.h"
#include "core/mesh/tet_mesh.h"
#include "core/swap/constrained_faces.h"

namespace cvtmesh {

struct RelocateStats {
  bool ok = false;     // every vertex is at its target and every unconstrained face is Delaunay
  int rounds = 0;      // move + flip rounds used
  int nb_flips = 0;    // 2-3 and 3-2 flips
  int nb_pending = 0;  // vertices not at their target on exit (ok = false)
  int nb_stuck = 0;    // non-Delaunay unconstrained faces no flip could remove (ok = false)
  // Every unconstrained face that may be non-Delaunay on exit (sorted vertex ids; a superset of
  // the nb_stuck faces: a face stuck in one round is not tested again).
  std::vector<FaceKey> stuck_faces;
};

// `target`: 3*#V coordinates (fixed vertices must keep theirs). On entry `mesh` is valid with its
// adjacency built. On exit it is valid (positively oriented, same constrained triangles) whether
// or not `ok`; if not ok, some vertices are between their old and target positions or some face
// is not locally Delaunay, and the caller rebuilds the tetrahedralization from the targets.
RelocateStats relocate_vertices(TetMesh& mesh, const ConstrainedFaces& constrained,
                                const std::vector<double>& target, int max_rounds = 4);

}  // namespace cvtmesh
