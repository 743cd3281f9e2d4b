// Validity checks (MMG chkmsh / WMTK is_connectivity_valid style). Every operation test calls
// them before and after.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

struct MeshCheck {
  bool ok = true;
  std::vector<std::string> problems;  // human-readable, at most a few dozen
  int nb_inverted = 0;                // elements with non-positive orientation (exact predicate)
  int nb_bad_adjacency = 0;
  int nb_open_faces = 0;  // boundary faces of the volume not covered by a constrained face
  int nb_dangling_constraints = 0;  // constrained faces that are not faces of any live element
};

// Checks a tet mesh: vertex ids in range, no dead tet referenced, adjacency symmetric and
// consistent with the vertex ids (must be built), adjacent tets on the two sides of their common
// face (not overlapping), every live tet positively oriented (orient3d), every boundary face of
// the tet complex is a constrained triangle and every constrained triangle is a face of the
// complex (boundary closed, interfaces present) -- of one tet, or of two adjacent ones.
MeshCheck check_mesh(const TetMesh& mesh);

// The largest id of a live tet that is not positively oriented (exact orient3d), -1 if none;
// in parallel (the result does not depend on the thread count). Vertex ids must be in range.
int last_non_positive_tet(const TetMesh& mesh);
// The same for a planar triangle mesh (counter-clockwise triangles, boundary edges; adjacent
// triangles on the two sides of their common edge, a boundary edge an edge of one triangle or of
// two adjacent ones).
MeshCheck check_mesh(const TriMesh2& mesh);

}  // namespace cvtmesh
