#include "core/swap/flip2d_quality.h"

#include <algorithm>

#include "core/swap/flip2d.h"

namespace cvtmesh {

bool flip2d_improves_quality(const TriMesh2& mesh, int slot, Measure m, double margin) {
  if (!flip2d_possible(mesh, slot)) return false;
  const int o = mesh.adj[slot];
  const int t = slot / 3, e = slot % 3;
  const int* tv = &mesh.tris[3 * t];
  const double* c = mesh.point(tv[e]);
  const double* a = mesh.point(tv[(e + 1) % 3]);
  const double* b = mesh.point(tv[(e + 2) % 3]);
  const double* d = mesh.point(mesh.tris[o]);
  const double before = std::min(tri_quality(c, a, b, 2, m), tri_quality(d, b, a, 2, m));
  const double after = std::min(tri_quality(c, a, d, 2, m), tri_quality(d, b, c, 2, m));
  return after > before + margin;
}

}  // namespace cvtmesh
