#include "core/mesh/check_quads2d.h"

#include "core/geometry/predicates.h"
#include "core/mesh/kept_quads.h"

namespace cvtmesh {

bool quad_strictly_convex(const double* a, const double* b, const double* c, const double* d) {
  return orient2d(a, b, c) > 0 && orient2d(b, c, d) > 0 && orient2d(c, d, a) > 0 &&
         orient2d(d, a, b) > 0;
}

QuadCheck check_quads2d(const TriMesh2& mesh) {
  QuadCheck r;
  const KeptQuads q = kept_quads(mesh);
  r.nb_quads = q.nb_quads();
  for (int k = 0; k < q.nb_quads(); ++k) {
    const int* v = &q.quads[4 * k];
    const double *a = mesh.point(v[0]), *b = mesh.point(v[1]), *c = mesh.point(v[2]),
                 *d = mesh.point(v[3]);
    if (quad_strictly_convex(a, b, c, d)) continue;
    // Twice the signed area: the sum of the two triangles of a diagonal.
    const bool inverted = orient2d(a, b, c) + orient2d(a, c, d) <= 0;
    (inverted ? r.nb_inverted : r.nb_not_convex)++;
    if (r.problems.size() < 10)
      r.problems.push_back("quadrangle " + std::to_string(q.tags[k]) + " (surface " +
                           std::to_string(q.entity[k]) + ") is " +
                           (inverted ? "inverted (turns against its surface)"
                                     : "not convex (a reflex or flat corner)"));
  }
  return r;
}

}  // namespace cvtmesh
