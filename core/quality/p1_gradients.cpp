#include "core/quality/p1_gradients.h"

namespace cvtmesh {

double tet_scaled_gradients(const double* a, const double* b, const double* c, const double* d,
                            double n[4][3]) {
  const double e[3][3] = {{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
                          {c[0] - a[0], c[1] - a[1], c[2] - a[2]},
                          {d[0] - a[0], d[1] - a[1], d[2] - a[2]}};
  auto cross = [](const double* u, const double* v, double* w) {
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
  };
  cross(e[1], e[2], n[1]);
  cross(e[2], e[0], n[2]);
  cross(e[0], e[1], n[3]);
  for (int k = 0; k < 3; ++k) n[0][k] = -(n[1][k] + n[2][k] + n[3][k]);
  return e[0][0] * n[1][0] + e[0][1] * n[1][1] + e[0][2] * n[1][2];
}

}  // namespace cvtmesh
