#include "core/cvt/lloyd3_anderson.h"

namespace cvtmesh {

std::vector<double> AndersonLloyd3::targets(const Lloyd3Cells& e, const std::vector<double>& xyz,
                                            const MoveSafeguard3& safe, LloydStep& s) {
  const std::vector<int>& free_ids = e.free_ids;
  const bool accelerated = depth_ > 0;
  if (accelerated && have_accepted_ && !last_was_fallback_ && free_ids == accepted_free_ &&
      e.energy > accepted_energy_ * (1 + 1e-12)) {
    // The accelerated step raised the energy: go back to the last accepted configuration and
    // take the plain (relaxed) Lloyd step from there instead. The energy stays monotone.
    s.restarted = true;
    last_was_fallback_ = true;
    mixer_.reset();
    // The mesh of accepted_xyz_ is gone (the move safeguards ran when the plain targets were
    // computed, on that mesh): the current, valid mesh moves to the targets.
    return with_free_positions(accepted_xyz_, accepted_free_, accepted_plain_);
  }
  // Plain relaxed Lloyd targets (kept for a restart), then the accelerated ones.
  const std::vector<double>& z = e.z;
  std::vector<double> g(z.size());
  for (std::size_t k = 0; k < g.size(); ++k) g[k] = z[k] + relaxation_ * (e.c[k] - z[k]);
  std::vector<double> plain(z.size());
  s.nb_limited += safe(g, plain);
  std::vector<double> next = plain;
  if (accelerated) {
    if (free_ids != accepted_free_) mixer_.reset();
    safe(mixer_.next(z, g), next);
  }
  have_accepted_ = true;
  last_was_fallback_ = false;
  accepted_energy_ = e.energy;
  accepted_xyz_ = xyz;
  accepted_free_ = free_ids;
  accepted_plain_ = std::move(plain);
  return with_free_positions(xyz, free_ids, next);
}

}  // namespace cvtmesh
