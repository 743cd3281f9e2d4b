// CGAL 5.5's tetrahedral_isotropic_remeshing (Tetrahedral_remeshing package: edge splits,
// collapses, flips and smoothing towards a target edge length) with the boundary protected
// (remesh_boundaries(false): the surface triangles and their vertices kept), on an existing mesh: a
// peer column of `cvtmesh compare` and `cvtmesh bench` (issue 17). Header-only, libcgal-dev.
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct CgalRemeshOptions {
  double target_edge_length = 0;  // <= 0: the input's mean edge length
  int iterations = 3;             // number_of_iterations, as in CGAL's remeshing examples
};

// Replaces `mesh`'s tets and interior vertices by CGAL's result (verify_peer checks that the
// boundary triangles are unchanged). Throws InvariantError if CGAL fails or breaks the mesh.
void cgal_remesh(TetMesh& mesh, const CgalRemeshOptions& options = {});

}  // namespace cvtmesh
