#include "core/cvt/lloyd3_reinsert.h"

#include "core/delaunay/relocate_vertices3.h"

namespace cvtmesh {

Reinsertion reinsert_vertices3(TetMesh& m, const ConstrainedFaces& constrained,
                               const std::vector<double>& target, bool local_flips,
                               double max_flip_leftover, Delaunay3& backend, LloydStep& s) {
  const int nv = m.nb_vertices();
  bool restored = false;
  bool delaunay = false;
  std::vector<FaceKey> stuck;
  if (local_flips) {
    RelocateStats rs = relocate_vertices(m, constrained, target);
    stuck = std::move(rs.stuck_faces);
    s.nb_flips = rs.nb_flips;
    s.nb_stuck_faces = rs.nb_stuck;
    s.nb_short_moves = rs.nb_pending;
    // Short moves leave a Delaunay mesh of the points where they are.
    delaunay = rs.nb_stuck == 0;
    // Faces the flips cannot make Delaunay are next to the boundary where the constrained
    // Delaunay mesh does not exist without Steiner points (TetGen's rebuild leaves such faces
    // too): they do not call for a rebuild. Vertices short of their targets do, beyond a few.
    restored = rs.ok || rs.nb_pending <= max_flip_leftover * nv;
  }
  // After successful flips every unconstrained face is locally Delaunay; TetGen's rebuild
  // leaves a few non-Delaunay faces near the boundary.
  Reinsertion r;
  r.delaunay = delaunay;
  r.faces_listed = restored;
  if (restored) r.non_delaunay_faces = std::move(stuck);
  if (!restored) {
    m.xyz = target;
    r.nb_steiner = backend.retetrahedralize(m).nb_steiner;
    s.rebuilt = true;
  }
  return r;
}

}  // namespace cvtmesh
