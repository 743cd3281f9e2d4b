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

void density_gradient(const TetMesh& m, int t, const std::vector<double>& rho, double* g) {
  const int* v = &m.tets[4 * t];
  const double* p0 = m.point(v[0]);
  double E[3][3], r[3];
  for (int k = 0; k < 3; ++k) {
    const double* pk = m.point(v[k + 1]);
    for (int d = 0; d < 3; ++d) E[k][d] = pk[d] - p0[d];
    r[k] = rho[v[k + 1]] - rho[v[0]];
  }
  const Vec3 c0 = cross(Vec3{E[1][0], E[1][1], E[1][2]}, Vec3{E[2][0], E[2][1], E[2][2]});
  const Vec3 c1 = cross(Vec3{E[2][0], E[2][1], E[2][2]}, Vec3{E[0][0], E[0][1], E[0][2]});
  const Vec3 c2 = cross(Vec3{E[0][0], E[0][1], E[0][2]}, Vec3{E[1][0], E[1][1], E[1][2]});
  const double det = E[0][0] * c0[0] + E[0][1] * c0[1] + E[0][2] * c0[2];
  // E g = r  =>  g = (r0 c0 + r1 c1 + r2 c2) / det (the columns of E^-1 are c_k / det).
  for (int d = 0; d < 3; ++d)
    g[d] = det == 0 ? 0.0 : (r[0] * c0[d] + r[1] * c1[d] + r[2] * c2[d]) / det;
}

namespace {

// x is inside the tet p0..p3 with every barycentric coordinate above 1e-6.
bool clearly_inside(const double* const p[4], const Vec3& x) {
  const double vol = tet_volume(p[0], p[1], p[2], p[3]);
  if (!(vol > 0)) return false;
  const double lim = 1e-6 * vol;
  return tet_volume(x.data(), p[1], p[2], p[3]) > lim &&
         tet_volume(p[0], x.data(), p[2], p[3]) > lim &&
         tet_volume(p[0], p[1], x.data(), p[3]) > lim &&
         tet_volume(p[0], p[1], p[2], x.data()) > lim;
}

}  // namespace

CellMesh prepare_cell_mesh(const TetMesh& m, const std::vector<double>* rho,
                           bool unconstrained_delaunay) {
  CellMesh c;
  prepare_cell_mesh(m, rho, unconstrained_delaunay, c);
  return c;
}

void prepare_cell_mesh(const TetMesh& m, const std::vector<double>* rho,
                       bool unconstrained_delaunay, CellMesh& c,
                       const std::vector<FaceKey>* suspect) {
  vertex_tets(m, c.star);  // reusing the arrays of the last call
  // The tets of the suspect faces: tested in full.
  std::vector<int> full;
  if (unconstrained_delaunay && suspect)
    for (const FaceKey& k : *suspect)
      for (const int* it = c.star.begin_of(k[0]); it != c.star.end_of(k[0]); ++it) {
        const int* tv = &m.tets[4 * *it];
        if (std::find(tv, tv + 4, k[1]) != tv + 4 && std::find(tv, tv + 4, k[2]) != tv + 4)
          full.push_back(*it);
      }
  std::sort(full.begin(), full.end());
  constrained_face_flags(m, c.constrained);
  c.eps = coordinate_eps(m);
  const int nt = m.nb_tets();
  c.dual_ok.assign(nt, 0);
  // Written for every dual_ok tet below, read only for those: no need to clear (the buffer is
  // reused from one iteration to the next; at 1M tets it is ~200 MB).
  // A few more tets than last time (the flips of a round add some) must not reallocate: a
  // vector's growth copies the old contents (not needed: every piece read is rewritten below)
  // into fresh pages, ~1.9 GB at 10M tets and old + new resident at once. Released first, then
  // allocated with room for 1/16 more; its growth writes nothing (DefaultInitAllocator): the
  // parallel loop below is the first to touch the pages (a serial zero-fill of the new part was
  // ~0.1 s at 1M tets, once per Lloyd run).
  const std::size_t pieces = 24 * static_cast<std::size_t>(nt);
  if (c.dual_piece.capacity() < pieces) {
    decltype(c.dual_piece)().swap(c.dual_piece);
    c.dual_piece.reserve(pieces + pieces / 16);
  }
  c.dual_piece.resize(pieces);
  if (rho)
    c.rho_grad.resize(3 * static_cast<std::size_t>(nt));
  else
    c.rho_grad.clear();
#pragma omp parallel for schedule(static, 256)
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tets[4 * t];
    if (tv[0] < 0) continue;
    const double* p[4] = {m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])};
    const Vec3 ct = tet_circumcenter(p[0], p[1], p[2], p[3]);
    if (rho) density_gradient(m, t, *rho, &c.rho_grad[3 * t]);
    bool ok = true;
    for (int f = 0; f < 4 && ok; ++f) {
      const int o = m.adj[4 * t + f];
      if (o < 0 || (unconstrained_delaunay && !c.constrained[4 * t + f] &&
                    !std::binary_search(full.begin(), full.end(), t)))
        continue;
      const int opp = m.tets[4 * (o / 4) + o % 4];
      ok = insphere(p[0], p[1], p[2], p[3], m.point(opp)) <= 0;
    }
    // The circumcentre is in the region if it is clearly inside t (floating-point barycentric
    // coordinates with a margin far above their rounding error), else if the exact walk reaches it.
    if (ok && !clearly_inside(p, ct))
      ok = locate_point(m, ct.data(), t, &c.constrained, 16).status == LocateStatus::kInside;
    c.dual_ok[t] = ok;
    if (ok)
      dual_tet_pieces(m, t, ct, rho, rho ? &c.rho_grad[3 * t] : nullptr, &c.dual_piece[24 * t]);
  }
}

}  // namespace cvtmesh
