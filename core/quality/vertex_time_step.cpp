#include "core/quality/vertex_time_step.h"

#include <array>

#include <cmath>
#include <limits>

#include "core/quality/p1_gradients.h"

namespace cvtmesh {

void tet_vertex_terms(const double* a, const double* b, const double* c, const double* d,
                      double kjj[4], double* mass) {
  double n[4][3];
  const double det = std::fabs(tet_scaled_gradients(a, b, c, d, n));
  if (det == 0 || !std::isfinite(det)) {
    for (int i = 0; i < 4; ++i) kjj[i] = 0;
    *mass = 0;
    return;
  }
  // grad phi_i = n_i / det, volume = det / 6: K_ii = |n_i|^2 / (6 det).
  for (int i = 0; i < 4; ++i)
    kjj[i] = (n[i][0] * n[i][0] + n[i][1] * n[i][1] + n[i][2] * n[i][2]) / (6.0 * det);
  *mass = det / 24.0;
}

double VertexTimeSteps::dt(int v) const {
  if (!(kdiag[v] > 0) || !(mass[v] > 0)) return std::numeric_limits<double>::infinity();
  return 2.0 / std::sqrt(kdiag[v] / mass[v]);
}

VertexTimeSteps vertex_time_steps(const TetMesh& mesh) {
  VertexTimeSteps s;
  s.kdiag.assign(mesh.nb_vertices(), 0.0);
  s.mass.assign(mesh.nb_vertices(), 0.0);
  // Each tet's terms in parallel, then summed in tet order: the same sums for any thread count.
  const int nt = mesh.nb_tets();
  std::vector<std::array<double, 5>> terms(static_cast<std::size_t>(nt));
#pragma omp parallel for schedule(static, 1024) if (nt > 1024)
  for (int t = 0; t < nt; ++t) {
    const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
    if (v[0] >= 0)
      tet_vertex_terms(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]),
                       terms[t].data(), &terms[t][4]);
  }
  for (int t = 0; t < nt; ++t) {
    const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
    if (v[0] < 0) continue;
    for (int i = 0; i < 4; ++i) {
      s.kdiag[v[i]] += terms[t][i];
      s.mass[v[i]] += terms[t][4];
    }
  }
  return s;
}

double min_vertex_time_step(const TetMesh& mesh) {
  const VertexTimeSteps s = vertex_time_steps(mesh);
  double m = std::numeric_limits<double>::infinity();
  for (int v = 0; v < mesh.nb_vertices(); ++v) m = std::min(m, s.dt(v));
  return m;
}

}  // namespace cvtmesh
