#include "core/mesh/reorient_tets.h"

#include <algorithm>
#include <utility>

#include "core/geometry/predicates.h"

namespace cvtmesh {

Reoriented reorient_tets(TetMesh& mesh) {
  Reoriented r;
  const int nt = mesh.nb_tets();
  long reoriented = 0, flat = 0;
  int first_flat = nt;
#pragma omp parallel for schedule(static, 1024) reduction(+ : reoriented, flat) \
    reduction(min : first_flat) if (nt > 1024)
  for (int t = 0; t < nt; ++t) {
    int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
    if (v[0] < 0) continue;
    const double o =
        orient3d(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]));
    if (o < 0) {
      std::swap(v[0], v[1]);
      ++reoriented;
    } else if (o == 0) {
      ++flat;
      first_flat = std::min(first_flat, t);
    }
  }
  r.nb_reoriented = reoriented;
  r.nb_flat = flat;
  r.first_flat = flat ? first_flat : -1;
  return r;
}

std::string reoriented_note(const std::string& what, long nb_reoriented, long nb_tets) {
  return what + ": " + std::to_string(nb_reoriented) + " of " + std::to_string(nb_tets) +
         " tetrahedra had negative volume (the other vertex order): turned positive";
}

}  // namespace cvtmesh
