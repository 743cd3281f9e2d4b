#include "core/cvt/lbfgs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cvtmesh {
namespace {

// F(x) = 1/2 x^T A x - b^T x with A symmetric positive definite and not diagonal (so the Jacobi
// "Lloyd" step -g / diag(A) is not the minimiser), the minimiser x* = A^-1 b known.
struct Quadratic {
  // A = tridiag(-1, 4, -1) scaled per row pair: SPD, condition number ~ 30.
  int n = 8;
  std::vector<double> diag, b, xstar;
  Quadratic() {
    diag.resize(n);
    for (int i = 0; i < n; ++i) diag[i] = i < n / 2 ? 4.0 : 40.0;
    xstar.resize(n);
    for (int i = 0; i < n; ++i) xstar[i] = std::sin(1.0 + i);
    b = apply(xstar);
  }
  double offdiag(int i, int j) const { return std::abs(i - j) == 1 ? -1.0 : 0.0; }
  std::vector<double> apply(const std::vector<double>& x) const {
    std::vector<double> y(n, 0);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) y[i] += (i == j ? diag[i] : offdiag(i, j)) * x[j];
    return y;
  }
  LbfgsPoint at(const std::vector<double>& x) const {
    LbfgsPoint p;
    p.x = x;
    const std::vector<double> ax = apply(x);
    p.gradient.resize(n);
    p.lloyd_step.resize(n);
    for (int i = 0; i < n; ++i) {
      p.energy += 0.5 * x[i] * ax[i] - b[i] * x[i];
      p.gradient[i] = ax[i] - b[i];
      p.lloyd_step[i] = -p.gradient[i] / diag[i];
    }
    p.initial_inverse_hessian = [d = diag](std::vector<double>& q) {
      for (std::size_t k = 0; k < q.size(); ++k) q[k] /= d[k];
    };
    return p;
  }
  double error(const std::vector<double>& x) const {
    double e = 0;
    for (int i = 0; i < n; ++i) e = std::max(e, std::abs(x[i] - xstar[i]));
    return e;
  }
};

LbfgsRules rules_2d() {
  LbfgsRules r;
  r.memory = 5;
  r.max_trials = 10;
  return r;
}

LbfgsRules rules_3d() {
  LbfgsRules r;
  r.memory = 5;
  r.max_trials = 3;
  r.backtrack = LbfgsRules::Backtrack::kQuadratic;
  r.armijo_on_actual_move = true;
  r.lloyd_direction_untested = true;
  r.fallback = LbfgsRules::Fallback::kLloydTrial;
  return r;
}

// Drives the minimiser on the quadratic (every trial evaluated as proposed); returns the
// evaluations needed to reach x* to 1e-10, and checks that the accepted energies never rise
// (after the first, untested step).
int evaluations_to_converge(const LbfgsRules& rules) {
  const Quadratic f;
  LbfgsMinimizer lb(rules);
  std::vector<double> x(f.n, 0.0);
  EXPECT_EQ(lb.tell(f.at(x)), LbfgsVerdict::kAccepted);
  double accepted = lb.current().energy;
  for (int it = 1; it <= 200; ++it) {
    const LbfgsPoint p = f.at(lb.trial_point());
    const LbfgsVerdict v = lb.tell(p);
    EXPECT_NE(v, LbfgsVerdict::kExhausted) << "at evaluation " << it;
    if (v == LbfgsVerdict::kAccepted) {
      if (it > 1) EXPECT_LE(lb.current().energy, accepted) << "at evaluation " << it;
      accepted = lb.current().energy;
      if (f.error(lb.current().x) < 1e-10) return it;
    }
  }
  ADD_FAILURE() << "no convergence in 200 evaluations";
  return -1;
}

TEST(Lbfgs, ConvergesOnAQuadraticWithEitherDimensionsRules) {
  // n = 8 unknowns: L-BFGS with memory 5 is far faster than Jacobi's ~ (condition number) steps.
  const int e2 = evaluations_to_converge(rules_2d());
  const int e3 = evaluations_to_converge(rules_3d());
  EXPECT_GT(e2, 0);
  EXPECT_GT(e3, 0);
  EXPECT_LT(e2, 60);
  EXPECT_LT(e3, 60);
}

TEST(Lbfgs, FirstDirectionIsTheLloydStep) {
  const Quadratic f;
  LbfgsMinimizer lb(rules_2d());
  const std::vector<double> x0(f.n, 0.5);
  const LbfgsPoint p = f.at(x0);
  lb.tell(p);
  const std::vector<double> t = lb.trial_point();
  for (int i = 0; i < f.n; ++i) EXPECT_NEAR(t[i], x0[i] + p.lloyd_step[i], 1e-15);
}

TEST(Lbfgs, HalvingLineSearchGivesUpAfterMaxTrialsAndRestarts) {
  const Quadratic f;
  LbfgsRules r = rules_2d();
  r.max_trials = 4;
  LbfgsMinimizer lb(r);
  lb.tell(f.at(std::vector<double>(f.n, 0.0)));
  double step = 1;
  for (int k = 1; k < 4; ++k) {
    LbfgsPoint bad = f.at(lb.trial_point());
    bad.energy = 1e30;  // never a sufficient decrease
    const LbfgsVerdict v = k % 2 ? lb.tell(bad) : lb.reject_unevaluated();
    EXPECT_EQ(v, LbfgsVerdict::kRejected);
    step *= 0.5;
    EXPECT_EQ(lb.step(), step);
  }
  EXPECT_EQ(lb.reject_unevaluated(), LbfgsVerdict::kExhausted);
  // kRestart: the next point is a first point, accepted whatever its energy.
  LbfgsPoint any = f.at(std::vector<double>(f.n, 3.0));
  any.energy = 1e30;
  EXPECT_EQ(lb.tell(any), LbfgsVerdict::kAccepted);
}

TEST(Lbfgs, QuadraticBacktrackingStaysInItsBracketAndFallsBackToAnUntestedLloydTrial) {
  const Quadratic f;
  LbfgsMinimizer lb(rules_3d());
  const std::vector<double> x0(f.n, 0.0);
  lb.tell(f.at(x0));
  lb.tell(f.at(lb.trial_point()));  // the first (Lloyd) direction: accepted untested
  const LbfgsPoint xk = lb.current();
  for (int k = 1; k < 3; ++k) {
    const double a = lb.step();
    LbfgsPoint bad = f.at(lb.trial_point());
    bad.energy = xk.energy + 1.0;  // a rise: rejected
    EXPECT_EQ(lb.tell(bad), LbfgsVerdict::kRejected);
    EXPECT_GE(lb.step(), 0.1 * a * (1 - 1e-15));
    EXPECT_LE(lb.step(), 0.5 * a * (1 + 1e-15));
  }
  LbfgsPoint bad = f.at(lb.trial_point());
  bad.energy = xk.energy + 1.0;
  EXPECT_EQ(lb.tell(bad), LbfgsVerdict::kExhausted);
  // kLloydTrial: the next trial is x_k + the Lloyd step of x_k, accepted as it comes.
  const std::vector<double> t = lb.trial_point();
  for (int i = 0; i < f.n; ++i) EXPECT_NEAR(t[i], xk.x[i] + xk.lloyd_step[i], 1e-15);
  LbfgsPoint lloyd = f.at(t);
  lloyd.energy = 1e30;
  EXPECT_EQ(lb.tell(lloyd), LbfgsVerdict::kAccepted);
}

}  // namespace
}  // namespace cvtmesh
