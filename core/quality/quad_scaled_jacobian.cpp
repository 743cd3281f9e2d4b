#include "core/quality/quad_scaled_jacobian.h"

#include <algorithm>
#include <cmath>

namespace cvtmesh {

double quad_scaled_jacobian(const double* a, const double* b, const double* c, const double* d) {
  const double* p[4] = {a, b, c, d};
  double e[4][2], len[4];
  for (int k = 0; k < 4; ++k) {  // edge k: corner k -> corner k+1
    e[k][0] = p[(k + 1) % 4][0] - p[k][0];
    e[k][1] = p[(k + 1) % 4][1] - p[k][1];
    len[k] = std::hypot(e[k][0], e[k][1]);
    if (len[k] == 0) return 0;
  }
  double sj = 1;
  for (int k = 0; k < 4; ++k) {  // corner k: the outgoing edge k and the incoming edge k-1
    const double* out = e[k];
    const double* in = e[(k + 3) % 4];
    const double cross = out[0] * -in[1] - out[1] * -in[0];  // out x (-in)
    sj = std::min(sj, cross / (len[k] * len[(k + 3) % 4]));
  }
  return sj;
}

}  // namespace cvtmesh
