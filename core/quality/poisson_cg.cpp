#include "core/quality/poisson_cg.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace cvtmesh {

PoissonCg poisson_cg(const P1System& s, double tolerance, int max_iterations) {
  PoissonCg r;
  const int n = s.n;
  r.x.assign(n, 0.0);
  std::vector<char> free(n, 0);
  std::vector<double> dinv(n, 0.0), b(n, 0.0);
  double bnorm = 0;
  for (int i = 0; i < n; ++i) {
    if (s.boundary[i] || !(s.mass[i] > 0)) continue;
    double diag = 0;
    for (long k = s.row_ptr[i]; k < s.row_ptr[i + 1]; ++k)
      if (s.col[k] == i) diag = s.val[k];
    if (!(diag > 0)) continue;
    free[i] = 1;
    dinv[i] = 1.0 / diag;
    b[i] = s.mass[i];
    bnorm += b[i] * b[i];
  }
  bnorm = std::sqrt(bnorm);
  if (bnorm == 0) {
    r.converged = true;
    return r;
  }
  // K restricted to the free vertices: products with vectors that are 0 on the fixed ones,
  // results masked.
  auto apply = [&](const std::vector<double>& v, std::vector<double>& out) {
    p1_multiply(s, v, out);
    for (int i = 0; i < n; ++i)
      if (!free[i]) out[i] = 0;
  };
  std::vector<double> res = b, z(n), p(n), q(n);
  double rz = 0;
  for (int i = 0; i < n; ++i) {
    z[i] = dinv[i] * res[i];
    p[i] = z[i];
    rz += res[i] * z[i];
  }
  // Lanczos coefficients of the preconditioned operator (Saad, Iterative Methods, 6.7.3).
  std::vector<double> diag_t, off_t;
  double alpha_prev = 0, beta_prev = 0;
  double rnorm = bnorm;
  int it = 0;
  while (it < max_iterations && rnorm > tolerance * bnorm) {
    apply(p, q);
    double pq = 0;
    for (int i = 0; i < n; ++i) pq += p[i] * q[i];
    if (!(pq > 0)) break;
    const double alpha = rz / pq;
    double rr = 0, rz_new = 0;
    for (int i = 0; i < n; ++i) {
      r.x[i] += alpha * p[i];
      res[i] -= alpha * q[i];
      z[i] = dinv[i] * res[i];
      rr += res[i] * res[i];
      rz_new += res[i] * z[i];
    }
    const double beta = rz_new / rz;
    diag_t.push_back(1.0 / alpha + (it > 0 ? beta_prev / alpha_prev : 0.0));
    if (it > 0) off_t.push_back(std::sqrt(beta_prev) / alpha_prev);
    alpha_prev = alpha;
    beta_prev = beta;
    rz = rz_new;
    for (int i = 0; i < n; ++i) p[i] = z[i] + beta * p[i];
    rnorm = std::sqrt(rr);
    ++it;
  }
  r.iterations = it;
  // The true residual.
  apply(r.x, q);
  double rr = 0;
  for (int i = 0; i < n; ++i)
    if (free[i]) rr += (b[i] - q[i]) * (b[i] - q[i]);
  r.residual = std::sqrt(rr) / bnorm;
  r.converged = rnorm <= tolerance * bnorm;
  if (!diag_t.empty()) {
    const int m = static_cast<int>(diag_t.size());
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es;
    es.computeFromTridiagonal(Eigen::Map<Eigen::VectorXd>(diag_t.data(), m),
                              Eigen::Map<Eigen::VectorXd>(off_t.data(), m - 1),
                              Eigen::EigenvaluesOnly);
    const double lo = es.eigenvalues()(0), hi = es.eigenvalues()(m - 1);
    r.condition = lo > 0 ? hi / lo : 0;
  }
  return r;
}

}  // namespace cvtmesh
