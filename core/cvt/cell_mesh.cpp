#include "core/cvt/cell_mesh.h"

#include <algorithm>
#include <cmath>

#include "core/cvt/voronoi_cell3.h"
#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/mesh/locate_point.h"

namespace cvtmesh {

double coordinate_eps(const TetMesh& m) {
  double emax = 0;
  for (double x : m.xyz) emax = std::max(emax, std::fabs(x));
  return 1e-12 * std::max(1.0, emax);
}

CellMesh prepare_cell_mesh(const TetMesh& m) {
  CellMesh c;
  c.star = build_vertex_star(m);
  c.constrained = constrained_face_flags(m);
  c.eps = coordinate_eps(m);
  const int nt = m.nb_tets();
  c.cc.assign(3 * static_cast<std::size_t>(nt), 0.0);
  c.face_cc.assign(12 * static_cast<std::size_t>(nt), 0.0);
  c.dual_ok.assign(nt, 0);
#pragma omp parallel for schedule(static, 256)
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tets[4 * t];
    if (tv[0] < 0) continue;
    const double* p[4] = {m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])};
    const Vec3 ct = tet_circumcenter(p[0], p[1], p[2], p[3]);
    for (int d = 0; d < 3; ++d) c.cc[3 * t + d] = ct[d];
    for (int f = 0; f < 4; ++f) {
      const Vec3 fc = tri_circumcenter3d(p[kTetFace[f][0]], p[kTetFace[f][1]], p[kTetFace[f][2]]);
      for (int d = 0; d < 3; ++d) c.face_cc[12 * t + 3 * f + d] = fc[d];
    }
    bool ok = true;
    for (int f = 0; f < 4 && ok; ++f) {
      const int o = m.adj[4 * t + f];
      if (o < 0) continue;
      const int opp = m.tets[4 * (o / 4) + o % 4];
      ok = insphere(p[0], p[1], p[2], p[3], m.point(opp)) <= 0;
    }
    if (ok)
      ok = locate_point(m, &c.cc[3 * t], t, &c.constrained, 16).status == LocateStatus::kInside;
    c.dual_ok[t] = ok;
  }
  return c;
}

}  // namespace cvtmesh
