#include "core/quality/explicit_time_step.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>
#include <vector>

namespace cvtmesh {

ExplicitTimeStep explicit_time_step(const P1System& s, double rel_tolerance, int max_iterations) {
  ExplicitTimeStep r;
  const int n = s.n;
  std::vector<double> w(n, 0.0);  // M^-1/2 (0 where the mass is 0)
  int nb_used = 0;
  for (int i = 0; i < n; ++i)
    if (s.mass[i] > 0) {
      w[i] = 1.0 / std::sqrt(s.mass[i]);
      ++nb_used;
    }
  if (nb_used == 0) return r;
  // Fixed pseudo-random start (the same stream everywhere: std::mt19937's is specified).
  std::mt19937 gen(12345u);
  std::vector<double> q(n, 0.0), q_prev(n, 0.0), u(n), y(n);
  double norm = 0;
  for (int i = 0; i < n; ++i)
    if (w[i] > 0) {
      q[i] = static_cast<double>(gen()) / 4294967296.0 - 0.5;
      norm += q[i] * q[i];
    }
  norm = std::sqrt(norm);
  for (double& v : q) v /= norm;
  std::vector<double> alpha, beta;
  double beta_prev = 0;
  const int kmax = std::min(max_iterations, nb_used);
  for (int k = 0; k < kmax; ++k) {
    // y = M^-1/2 K M^-1/2 q - beta_prev q_prev
    for (int i = 0; i < n; ++i) u[i] = w[i] * q[i];
    p1_multiply(s, u, y);
    double a = 0;
    for (int i = 0; i < n; ++i) {
      y[i] = w[i] * y[i] - beta_prev * q_prev[i];
      a += y[i] * q[i];
    }
    double b = 0;
    for (int i = 0; i < n; ++i) {
      y[i] -= a * q[i];
      b += y[i] * y[i];
    }
    b = std::sqrt(b);
    alpha.push_back(a);
    beta.push_back(b);
    r.iterations = k + 1;
    const bool last = k + 1 == kmax;
    if (k % 4 == 3 || last || b == 0) {
      const int m = k + 1;
      Eigen::VectorXd d = Eigen::Map<Eigen::VectorXd>(alpha.data(), m);
      Eigen::VectorXd e = m > 1 ? Eigen::VectorXd(Eigen::Map<Eigen::VectorXd>(beta.data(), m - 1))
                                : Eigen::VectorXd();
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es;
      es.computeFromTridiagonal(d, e, Eigen::ComputeEigenvectors);
      const double theta = es.eigenvalues()(m - 1);
      const double s_last = es.eigenvectors()(m - 1, m - 1);
      r.lambda_max = theta;
      if (b * std::fabs(s_last) <= rel_tolerance * std::fabs(theta) || b == 0) {
        r.converged = true;
        break;
      }
    }
    for (int i = 0; i < n; ++i) {
      q_prev[i] = q[i];
      q[i] = y[i] / b;
    }
    beta_prev = b;
  }
  r.time_step = r.lambda_max > 0 ? 2.0 / std::sqrt(r.lambda_max) : 0;
  return r;
}

}  // namespace cvtmesh
