// Vertex -> boundary (constrained) triangles incidence, in compressed (CSR) form, and the surface
// normal of a boundary vertex from its fan.
#pragma once
#include <vector>

#include "core/geometry/vec3.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct BoundaryFans {
  // #V+1 offsets: the triangles around v are tris[offset[v] .. offset[v+1]-1] (ids into mesh.tris).
  std::vector<int> offset;
  std::vector<int> tris;
  const int* begin_of(int v) const { return tris.data() + offset[v]; }
  const int* end_of(int v) const { return tris.data() + offset[v + 1]; }
};

// O(#V + #F). Stays valid while only coordinates change.
BoundaryFans boundary_fans(const TetMesh& mesh);

// The area-weighted unit normal of v's fan at the current coordinates (each triangle's normal
// taken on the side of the first one: the fan of a surface vertex is nearly flat), or {0,0,0}
// for a vertex on no triangle or a degenerate fan.
Vec3 fan_normal(const TetMesh& mesh, const BoundaryFans& fans, int v);

}  // namespace cvtmesh
