#include "core/mesh/bounding_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cvtmesh {

double bounding_box_diagonal(const TetMesh& m) {
  double lo[3] = {std::numeric_limits<double>::infinity(), lo[0], lo[0]};
  double hi[3] = {-lo[0], -lo[0], -lo[0]};
  for (int v = 0; v < m.nb_vertices(); ++v)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], m.point(v)[d]);
      hi[d] = std::max(hi[d], m.point(v)[d]);
    }
  if (m.nb_vertices() == 0) return 0;
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

}  // namespace cvtmesh
