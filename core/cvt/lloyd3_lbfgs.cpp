#include "core/cvt/lloyd3_lbfgs.h"

namespace cvtmesh {
namespace {

LbfgsRules rules_3d(int memory) {
  LbfgsRules r;
  r.memory = memory;
  r.max_trials = 3;
  r.backtrack = LbfgsRules::Backtrack::kQuadratic;
  r.armijo_on_actual_move = true;
  // The density is interpolated on the mesh, so even the Lloyd step can raise F slightly;
  // shorter steps along it would only cost evaluations.
  r.lloyd_direction_untested = true;
  r.fallback = LbfgsRules::Fallback::kLloydTrial;
  return r;
}

}  // namespace

LbfgsLloyd3::LbfgsLloyd3(int memory, double relaxation)
    : relaxation_(relaxation), lbfgs_(rules_3d(memory)) {}

std::vector<double> LbfgsLloyd3::targets(const Lloyd3Cells& e, const std::vector<double>& xyz,
                                         const MoveSafeguard3& safe, LloydStep& s) {
  const std::size_t n = e.z.size();
  LbfgsPoint p;
  p.energy = e.energy;
  p.x = e.z;
  p.gradient.resize(n);
  p.lloyd_step.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    p.gradient[k] = 2 * e.mass[k / 3] * (e.z[k] - e.c[k]);
    p.lloyd_step[k] = e.c[k] - e.z[k];
  }
  // H0 = diag(relaxation / (2 m_i)): the first direction is the relaxed Lloyd step.
  p.initial_inverse_hessian = [mass = e.mass, omega = relaxation_](std::vector<double>& q) {
    for (std::size_t k = 0; k < q.size(); ++k) {
      const double m = mass[k / 3];
      q[k] = m > 0 ? omega * q[k] / (2 * m) : 0;
    }
  };
  if (e.free_ids != free_ids_) {  // a rebuild changed the vertex set: start afresh
    lbfgs_.reset();
    free_ids_ = e.free_ids;
  }
  if (lbfgs_.tell(std::move(p)) != LbfgsVerdict::kAccepted) s.restarted = true;
  // x_k + step * direction, every free vertex through the move safeguard of the current mesh.
  std::vector<double> safe_xyz;
  s.nb_limited += safe(lbfgs_.trial_point(), safe_xyz);
  return with_free_positions(xyz, free_ids_, safe_xyz);
}

}  // namespace cvtmesh
