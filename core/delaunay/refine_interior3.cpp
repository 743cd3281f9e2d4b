#include "core/delaunay/refine_interior3.h"

#include <cstdio>
#include <string>

#include "core/util/error.h"

namespace cvtmesh {

Delaunay3Stats refine_interior3(TetMesh& mesh, double radius_edge) {
  if (!(radius_edge > 1))
    throw InvariantError("refine_interior3: the radius-edge bound must exceed 1");
  char switches[64];
  // q: the radius-edge bound (and TetGen's default dihedral bound of 0: none); O0: no flips.
  std::snprintf(switches, sizeof switches, "pq%.6gYAzQMO0", radius_edge);
  return tetgen_rebuild(mesh, switches, "the interior refinement (refine_interior3)");
}

}  // namespace cvtmesh
