// A free-boundary result whose boundary surface crosses itself (two boundary triangles intersect
// improperly where the input's did not: igl_cheburashka, igl_armadillo) repaired locally: the
// moved vertices of the crossing triangles go back to their input positions (exactly on the input
// boundary), then those of the triangles within k edges of them (k = 1 .. max_rounds) while
// crossings remain. A vertex goes back only if every tet of its star stays positively oriented
// (exact orient3d). Connectivity never changes. Serial, in vertex order: deterministic.
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct RestoreCrossingStats {
  long nb_pairs_before = 0;  // crossing pairs found at the start (at most 1000 counted)
  long nb_pairs_after = 0;   // left at the end (0: repaired)
  long nb_restored = 0;      // vertices moved back to their input positions
  int rounds = 0;
};

// mesh's vertices v < input.nb_vertices() are input's vertex v (optimize keeps the ids); mesh.adj
// is not needed. Does nothing if the input's boundary crosses itself (then the crossings are not
// the optimizer's).
RestoreCrossingStats restore_crossing_vertices(TetMesh& mesh, const TetMesh& input,
                                               int max_rounds = 4);

}  // namespace cvtmesh
