// L-BFGS on the CVT energy for the 3D iteration (lloyd3.h: Lloyd3Options::lbfgs_memory), on the
// shared minimiser (lbfgs.h) with the 3D rules: every trial is one iteration (one evaluation of
// the cells); Armijo on the actual, safeguarded moves; at most 3 trials along a direction
// (quadratic backtracking), then the plain Lloyd step from x_k, accepted as it comes; initial
// inverse Hessian diag(relaxation / (2 m_i)), the first direction (empty memory) taken whole.
#pragma once
#include <vector>

#include "core/cvt/lbfgs.h"
#include "core/cvt/lloyd.h"
#include "core/cvt/lloyd3_cells.h"
#include "core/cvt/move_safeguard3.h"

namespace cvtmesh {

class LbfgsLloyd3 {
 public:
  LbfgsLloyd3(int memory, double relaxation);

  // Tells the minimiser the evaluation `e` of the current mesh (the first point, or the pending
  // trial) and returns the positions of every vertex (3*#V; xyz: the current ones) for its next
  // trial. A rejected trial reports s.restarted; shortened moves s.nb_limited.
  std::vector<double> targets(const Lloyd3Cells& e, const std::vector<double>& xyz,
                              const MoveSafeguard3& safe, LloydStep& s);

 private:
  double relaxation_;
  LbfgsMinimizer lbfgs_;
  std::vector<int> free_ids_;  // of the minimiser's points (a rebuild may change them)
};

}  // namespace cvtmesh
