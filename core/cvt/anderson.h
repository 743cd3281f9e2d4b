// Anderson acceleration (type II, depth m) of a fixed-point iteration x <- G(x), used to speed up
// Lloyd's iteration (G = the centroid map). Dimension-agnostic: works on flat vectors.
#pragma once
#include <vector>

namespace cvtmesh {

class AndersonMixer {
 public:
  explicit AndersonMixer(int depth, double regularization = 1e-10);
  // Given the current iterate x and its image g = G(x), returns the next iterate. The first call
  // (or after reset) returns g.
  std::vector<double> next(const std::vector<double>& x, const std::vector<double>& g);
  void reset();
  int depth() const { return depth_; }

 private:
  int depth_;
  double reg_;
  std::vector<std::vector<double>> dr_, dg_;  // differences of residuals and images
  std::vector<double> last_r_, last_g_;
};

}  // namespace cvtmesh
