// The relaxed, optionally Anderson-accelerated, Lloyd step of the 3D iteration (lloyd3.h:
// Lloyd3Options::relaxation and anderson_depth). An accelerated step that raised the energy is
// undone: the plain relaxed step from the last accepted configuration is taken instead, and
// accepted as it comes (the P1 density makes even plain Lloyd not exactly monotone: no endless
// restarts).
#pragma once
#include <vector>

#include "core/cvt/anderson.h"
#include "core/cvt/lloyd.h"
#include "core/cvt/lloyd3_cells.h"
#include "core/cvt/move_safeguard3.h"

namespace cvtmesh {

class AndersonLloyd3 {
 public:
  AndersonLloyd3(double relaxation, int anderson_depth)
      : relaxation_(relaxation), depth_(anderson_depth), mixer_(anderson_depth) {}

  // The next positions of every vertex (3*#V; xyz: the current ones) from the evaluation `e` of
  // the current mesh. Reports s.restarted and s.nb_limited.
  std::vector<double> targets(const Lloyd3Cells& e, const std::vector<double>& xyz,
                              const MoveSafeguard3& safe, LloydStep& s);

 private:
  double relaxation_;
  int depth_;
  AndersonMixer mixer_;
  bool have_accepted_ = false;
  bool last_was_fallback_ = false;  // the last step was the plain one after a restart
  double accepted_energy_ = 0;
  std::vector<double> accepted_xyz_, accepted_plain_;  // all vertices; plain targets of the free
  std::vector<int> accepted_free_;
};

}  // namespace cvtmesh
