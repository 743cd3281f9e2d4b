// Tets given in the other vertex order (negative volume: a tool of the opposite convention, or a
// writer that mixes both) turned positive, so that such a file is read rather than refused.
#pragma once
#include <string>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct Reoriented {
  long nb_reoriented = 0;  // negative tets whose first two vertices were swapped
  long nb_flat = 0;        // zero-volume tets (left as they are: the caller refuses them)
  int first_flat = -1;     // the first of them
};

// Exact orient3d on every tet; negative ones get vertices 0 and 1 swapped. Whether the result is
// a valid mesh (no two tets on the same side of their common face: a tangled mesh is not a
// mislabelled one) is for check_mesh to say, after build_adjacency.
Reoriented reorient_tets(TetMesh& mesh);

// The reader's note: "<what>: N of M tetrahedra had negative volume (the other vertex order):
// turned positive".
std::string reoriented_note(const std::string& what, long nb_reoriented, long nb_tets);

}  // namespace cvtmesh
