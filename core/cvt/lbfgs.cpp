#include "core/cvt/lbfgs.h"

#include <algorithm>
#include <cmath>

namespace cvtmesh {
namespace {

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double r = 0;
  for (std::size_t k = 0; k < a.size(); ++k) r += a[k] * b[k];
  return r;
}

}  // namespace

void LbfgsMinimizer::reset() {
  have_point_ = false;
  xk_ = LbfgsPoint{};
  dir_.clear();
  gd_ = 0;
  step_ = 1;
  trials_ = 0;
  untested_ = false;
  clear_memory();
}

LbfgsVerdict LbfgsMinimizer::tell(LbfgsPoint p) {
  if (!have_point_) {
    accept(std::move(p));
    return LbfgsVerdict::kAccepted;
  }
  // p is the pending trial x_k + s.
  const std::size_t n = p.x.size();
  std::vector<double> s(n);
  for (std::size_t k = 0; k < n; ++k) s[k] = p.x[k] - xk_.x[k];
  bool sufficient;
  double slope;
  if (rules_.armijo_on_actual_move) {
    slope = dot(xk_.gradient, s);
    sufficient = slope < 0 && p.energy <= xk_.energy + 1e-4 * slope;
  } else {
    slope = step_ * gd_;
    sufficient = p.energy <= xk_.energy + 1e-4 * step_ * gd_;
  }
  if (!sufficient && !untested_) return reject(true, p.energy, slope);
  // Accepted: memory update with the actual step and the gradient change.
  std::vector<double> y(n);
  for (std::size_t k = 0; k < n; ++k) y[k] = p.gradient[k] - xk_.gradient[k];
  push_pair(std::move(s), std::move(y));
  accept(std::move(p));
  return LbfgsVerdict::kAccepted;
}

LbfgsVerdict LbfgsMinimizer::reject_unevaluated() {
  return reject(false, 0, 0);
}

LbfgsVerdict LbfgsMinimizer::reject(bool evaluated, double energy, double slope) {
  if (++trials_ < rules_.max_trials) {
    const double a = step_;
    if (rules_.backtrack == LbfgsRules::Backtrack::kQuadratic && evaluated) {
      const double denom = 2 * (energy - xk_.energy - slope);
      const double an = denom > 0 ? -slope * a / denom : 0.5 * a;
      step_ = std::clamp(an, 0.1 * a, 0.5 * a);
    } else {
      step_ = a * 0.5;
    }
    return LbfgsVerdict::kRejected;
  }
  clear_memory();
  if (rules_.fallback == LbfgsRules::Fallback::kLloydTrial) {
    dir_ = xk_.lloyd_step;
    step_ = 1.0;
    untested_ = true;
  } else {
    have_point_ = false;
  }
  return LbfgsVerdict::kExhausted;
}

std::vector<double> LbfgsMinimizer::trial_point() const {
  std::vector<double> x(dir_.size());
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = xk_.x[k] + step_ * dir_[k];
  return x;
}

void LbfgsMinimizer::accept(LbfgsPoint p) {
  xk_ = std::move(p);
  have_point_ = true;
  trials_ = 0;
  new_direction();
}

void LbfgsMinimizer::push_pair(std::vector<double> s, std::vector<double> y) {
  const double sy = dot(s, y);
  if (!(sy > 1e-12 * std::sqrt(dot(s, s) * dot(y, y)))) return;  // no curvature: skipped
  s_.push_back(std::move(s));
  y_.push_back(std::move(y));
  rho_.push_back(1 / sy);
  if (static_cast<int>(s_.size()) > rules_.memory) {
    s_.erase(s_.begin());
    y_.erase(y_.begin());
    rho_.erase(rho_.begin());
  }
}

// Two-loop recursion: dir = -H g at x_k, H0 from the point.
void LbfgsMinimizer::new_direction() {
  const std::vector<double>& g = xk_.gradient;
  const std::size_t n = g.size();
  std::vector<double> q = g;
  const int m = static_cast<int>(s_.size());
  std::vector<double> alpha(m);
  for (int i = m - 1; i >= 0; --i) {
    alpha[i] = rho_[i] * dot(s_[i], q);
    for (std::size_t k = 0; k < n; ++k) q[k] -= alpha[i] * y_[i][k];
  }
  xk_.initial_inverse_hessian(q);
  for (int i = 0; i < m; ++i) {
    const double beta = rho_[i] * dot(y_[i], q);
    for (std::size_t k = 0; k < n; ++k) q[k] += s_[i][k] * (alpha[i] - beta);
  }
  dir_.assign(n, 0);
  for (std::size_t k = 0; k < n; ++k) dir_[k] = -q[k];
  if (!(dot(g, dir_) < 0)) {  // not a descent direction: Lloyd's
    clear_memory();
    dir_ = xk_.lloyd_step;
  }
  gd_ = dot(g, dir_);
  untested_ = rules_.lloyd_direction_untested && s_.empty();
  step_ = 1;
}

void LbfgsMinimizer::clear_memory() {
  s_.clear();
  y_.clear();
  rho_.clear();
}

}  // namespace cvtmesh
