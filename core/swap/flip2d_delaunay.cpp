#include "core/swap/flip2d_delaunay.h"

#include "core/geometry/predicates.h"

namespace cvtmesh {

bool is_locally_delaunay2d(const TriMesh2& mesh, int slot) {
  const int o = mesh.adj[slot];
  if (o < 0) return true;
  const int* tv = &mesh.tris[3 * (slot / 3)];
  const int d = mesh.tris[o];
  return incircle(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]), mesh.point(d)) <= 0;
}

}  // namespace cvtmesh
