#include "core/quality/element_time_step.h"

#include <Eigen/Dense>
#include <cmath>

namespace cvtmesh {

double tet_time_step(const double* a, const double* b, const double* c, const double* d) {
  // With E = [b-a c-a d-a] and det = det E (6 V), the gradients of the barycentric functions of
  // b, c, d are n_1 / det, n_2 / det, n_3 / det with n_1 = e2 x e3, n_2 = e3 x e1, n_3 = e1 x e2
  // (the rows of det E^-1); that of a is minus their sum. S = sum n_i n_i^T = det^2 G^T G.
  Eigen::Vector3d e1(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  Eigen::Vector3d e2(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
  Eigen::Vector3d e3(d[0] - a[0], d[1] - a[1], d[2] - a[2]);
  const Eigen::Vector3d n1 = e2.cross(e3), n2 = e3.cross(e1), n3 = e1.cross(e2);
  const double det = e1.dot(n1);
  if (det == 0 || !std::isfinite(det)) return 0;
  const Eigen::Vector3d n0 = -(n1 + n2 + n3);
  const Eigen::Matrix3d S =
      n0 * n0.transpose() + n1 * n1.transpose() + n2 * n2.transpose() + n3 * n3.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
  es.computeDirect(S, Eigen::EigenvaluesOnly);
  const double lmax = es.eigenvalues()(2);
  if (!(lmax > 0)) return 0;
  // lambda_max(M_e^-1 K_e) = 4 lambda_max(G G^T) = 4 lmax / det^2: dt = 2 / sqrt of it.
  return det / std::sqrt(lmax);
}

double tri_time_step(const double* a, const double* b, const double* c) {
  // det = 2 A; gradients of b, c: (e2y, -e2x) / det, (-e1y, e1x) / det; of a: minus the sum.
  const double e1x = b[0] - a[0], e1y = b[1] - a[1], e2x = c[0] - a[0], e2y = c[1] - a[1];
  const double det = e1x * e2y - e1y * e2x;
  if (det == 0 || !std::isfinite(det)) return 0;
  const double n[3][2] = {{-(e2y - e1y), -(-e2x + e1x)}, {e2y, -e2x}, {-e1y, e1x}};
  double sxx = 0, sxy = 0, syy = 0;
  for (const auto& g : n) {
    sxx += g[0] * g[0];
    sxy += g[0] * g[1];
    syy += g[1] * g[1];
  }
  const double lmax = 0.5 * (sxx + syy + std::sqrt((sxx - syy) * (sxx - syy) + 4 * sxy * sxy));
  if (!(lmax > 0)) return 0;
  // lambda_max(M_e^-1 K_e) = 3 lambda_max(G G^T) = 3 lmax / det^2.
  return 2.0 * det / std::sqrt(3.0 * lmax);
}

}  // namespace cvtmesh
