// L-BFGS on the CVT energy F (Liu et al. 2009, "On centroidal Voronoi tessellation - energy
// smoothness and fast computation"), shared by the 2D and 3D Lloyd problems. Dimension-agnostic:
// works on the flat vector x of the free coordinates (2 or 3 per free vertex), like anderson.h.
//
// Reverse communication: the caller evaluates points (cells -> F, gradient, Lloyd step) and tells
// the minimiser; the minimiser decides whether the point is accepted (the new x_k: memory update,
// new direction) or rejected (a shorter trial along the same direction follows), and when the
// line search gives up (the caller then takes the Lloyd step). The caller turns a trial
// x_k + step * direction into actual positions through its safeguards (so a trial can be one
// iteration of the Lloyd loop, as in 3D, or one try inside an iteration, as in 2D).
//
// The rules that differ between the dimensions are LbfgsRules; each keeps its exact behaviour.
#pragma once
#include <functional>
#include <vector>

namespace cvtmesh {

// An evaluated configuration. All vectors: #x (the free coordinates, 2 or 3 per free vertex).
struct LbfgsPoint {
  double energy = 0;               // F at x
  std::vector<double> x;           // the free coordinates
  std::vector<double> gradient;    // dF/dx = 2 m_i (z_i - c_i)
  std::vector<double> lloyd_step;  // the Lloyd step from x: the direction when -H g is no descent
  // q <- H0 q: the initial inverse Hessian at x (used only if the point is accepted).
  std::function<void(std::vector<double>& q)> initial_inverse_hessian;
};

struct LbfgsRules {
  int memory = 5;  // (s, y) pairs kept
  // Trials along one direction before the line search gives up (LbfgsVerdict::kExhausted).
  int max_trials = 3;
  // The next step after a rejected trial: half of it (kHalve), or the minimiser of the quadratic
  // through F(x_k), its slope along the trial and F(trial), clamped to [0.1, 0.5] of the step
  // (kQuadratic; trials that were not evaluated are halved).
  enum class Backtrack { kHalve, kQuadratic } backtrack = Backtrack::kHalve;
  // Armijo's sufficient decrease F(trial) <= F(x_k) + 1e-4 * slope, with slope = g . (x - x_k) on
  // the actual, safeguarded move (true, and then a move that does not descend is rejected), or
  // step * g . direction on the nominal one (false).
  bool armijo_on_actual_move = false;
  // With an empty memory the direction is the Lloyd step: its trial is accepted untested, as the
  // plain Lloyd iteration would take it (true), or line-searched like any other (false).
  bool lloyd_direction_untested = false;
  // When the line search gives up: the caller moves along the Lloyd step from x_k
  // (trial_point() with step 1) and that trial is accepted as it comes and joins the memory
  // (kLloydTrial); or the caller takes its own plain Lloyd step and the minimiser starts afresh
  // from where it lands (kRestart: the next point told is a first point).
  enum class Fallback { kLloydTrial, kRestart } fallback = Fallback::kRestart;
};

enum class LbfgsVerdict {
  kAccepted,  // the point is the new x_k; trial_point() is the first trial of its new direction
  kRejected,  // the trial is refused; trial_point() is a shorter one along the same direction
  kExhausted  // the line search gave up (the memory is cleared): take the Lloyd step (see Fallback)
};

class LbfgsMinimizer {
 public:
  explicit LbfgsMinimizer(const LbfgsRules& rules) : rules_(rules) {}

  // Forgets the point and the memory (the set of free vertices changed): the next point told is
  // a first point.
  void reset();

  // The evaluation of the pending trial (or a first point: accepted). After kAccepted the new
  // direction is computed (two-loop recursion with the point's H0; the Lloyd step if -H g is not
  // a descent direction).
  LbfgsVerdict tell(LbfgsPoint p);
  // The pending trial could not be evaluated (its targets leave the domain): rejected; the next
  // trial is half as long. kExhausted after max_trials.
  LbfgsVerdict reject_unevaluated();

  // x_k + step * direction (#x): the pending trial before the caller's safeguards.
  std::vector<double> trial_point() const;
  double step() const { return step_; }
  const LbfgsPoint& current() const { return xk_; }  // x_k (after a first tell)

 private:
  LbfgsVerdict reject(bool evaluated, double energy, double slope);
  void accept(LbfgsPoint p);
  void push_pair(std::vector<double> s, std::vector<double> y);
  void new_direction();
  void clear_memory();

  LbfgsRules rules_;
  bool have_point_ = false;
  LbfgsPoint xk_;
  std::vector<double> dir_;
  double gd_ = 0;          // g_k . dir_
  double step_ = 1;        // of the pending trial
  int trials_ = 0;         // rejected trials along dir_
  bool untested_ = false;  // the pending trial is accepted as it comes
  std::vector<std::vector<double>> s_, y_;
  std::vector<double> rho_;  // 1 / (s . y)
};

}  // namespace cvtmesh
