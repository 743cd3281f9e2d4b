#include "core/cvt/anderson.h"

#include <cmath>

namespace cvtmesh {

AndersonMixer::AndersonMixer(int depth, double regularization)
    : depth_(depth), reg_(regularization) {}

void AndersonMixer::reset() {
  dr_.clear();
  dg_.clear();
  last_r_.clear();
  last_g_.clear();
}

std::vector<double> AndersonMixer::next(const std::vector<double>& x,
                                        const std::vector<double>& g) {
  const std::size_t n = x.size();
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = g[i] - x[i];
  if (!last_r_.empty() && last_r_.size() == n) {
    std::vector<double> a(n), b(n);
    for (std::size_t i = 0; i < n; ++i) {
      a[i] = r[i] - last_r_[i];
      b[i] = g[i] - last_g_[i];
    }
    dr_.push_back(std::move(a));
    dg_.push_back(std::move(b));
    if (static_cast<int>(dr_.size()) > depth_) {
      dr_.erase(dr_.begin());
      dg_.erase(dg_.begin());
    }
  }
  last_r_ = r;
  last_g_ = g;
  const int m = static_cast<int>(dr_.size());
  if (m == 0 || depth_ <= 0) return g;
  // gamma = argmin |r - DR gamma|^2 via the (regularized) normal equations, Gaussian elimination.
  std::vector<double> A(m * m), rhs(m);
  double scale = 0;
  for (int i = 0; i < m; ++i) {
    for (int j = 0; j <= i; ++j) {
      double s = 0;
      for (std::size_t k = 0; k < n; ++k) s += dr_[i][k] * dr_[j][k];
      A[i * m + j] = A[j * m + i] = s;
    }
    scale = std::max(scale, A[i * m + i]);
    double s = 0;
    for (std::size_t k = 0; k < n; ++k) s += dr_[i][k] * r[k];
    rhs[i] = s;
  }
  if (scale == 0) return g;
  for (int i = 0; i < m; ++i) A[i * m + i] += reg_ * scale;
  std::vector<double> gamma = rhs;
  for (int c = 0; c < m; ++c) {
    int piv = c;
    for (int i = c + 1; i < m; ++i)
      if (std::fabs(A[i * m + c]) > std::fabs(A[piv * m + c])) piv = i;
    if (A[piv * m + c] == 0) return g;
    if (piv != c) {
      for (int j = 0; j < m; ++j) std::swap(A[c * m + j], A[piv * m + j]);
      std::swap(gamma[c], gamma[piv]);
    }
    for (int i = c + 1; i < m; ++i) {
      const double f = A[i * m + c] / A[c * m + c];
      for (int j = c; j < m; ++j) A[i * m + j] -= f * A[c * m + j];
      gamma[i] -= f * gamma[c];
    }
  }
  for (int c = m - 1; c >= 0; --c) {
    double s = gamma[c];
    for (int j = c + 1; j < m; ++j) s -= A[c * m + j] * gamma[j];
    gamma[c] = s / A[c * m + c];
  }
  std::vector<double> out = g;
  for (int j = 0; j < m; ++j)
    for (std::size_t k = 0; k < n; ++k) out[k] -= gamma[j] * dg_[j][k];
  return out;
}

}  // namespace cvtmesh
