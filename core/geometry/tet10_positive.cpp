#include "core/geometry/tet10_positive.h"

#include "core/geometry/predicates.h"

namespace cvtmesh {

const int kTet10Edge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

namespace {

// Index in kTet10Edge of the edge (i, j), i != j.
int edge_index(int i, int j) {
  if (i > j) {
    const int t = i;
    i = j;
    j = t;
  }
  for (int k = 0; k < 6; ++k)
    if (kTet10Edge[k][0] == i && kTet10Edge[k][1] == j) return k;
  return -1;
}

// det of the Jacobian of X(lambda) = sum_i x_i l_i (2 l_i - 1) + sum_{i<j} 4 x_ij l_i l_j at the
// barycentric point l, with xi = (l1, l2, l3) and l0 = 1 - l1 - l2 - l3.
double jacobian(const double* const c[4], const double* const m[6], const double l[4]) {
  double d[4][3];  // dX/dl_i
  for (int i = 0; i < 4; ++i)
    for (int a = 0; a < 3; ++a) {
      double s = c[i][a] * (4 * l[i] - 1);
      for (int j = 0; j < 4; ++j)
        if (j != i) s += 4 * m[edge_index(i, j)][a] * l[j];
      d[i][a] = s;
    }
  double J[3][3];
  for (int k = 0; k < 3; ++k)
    for (int a = 0; a < 3; ++a) J[k][a] = d[k + 1][a] - d[0][a];
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
         J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

}  // namespace

bool tet10_positive(const double* const c[4], const double* const m[6]) {
  const double* const m01 = m[0];
  const double* const m02 = m[1];
  const double* const m03 = m[2];
  const double* const m12 = m[3];
  const double* const m13 = m[4];
  const double* const m23 = m[5];
  // Bey's refinement (with two children reordered so that all have the parent's orientation).
  const double* const sub[8][4] = {
      {c[0], m01, m02, m03}, {m01, c[1], m12, m13}, {m02, m12, c[2], m23}, {m03, m13, m23, c[3]},
      {m01, m02, m03, m13},  {m01, m02, m13, m12},  {m02, m03, m13, m23},  {m02, m12, m23, m13}};
  for (const auto& t : sub)
    if (!(orient3d(t[0], t[1], t[2], t[3]) > 0)) return false;
  // The Jacobian's sign in our orientation: for the straight reference tet it is 6 V > 0 with
  // columns x1 - x0, x2 - x0, x3 - x0; orient3d > 0 means (x1-x0).((x2-x0)x(x3-x0)) > 0, the same
  // determinant.
  static const double kNodes[11][4] = {{1, 0, 0, 0},   {0, 1, 0, 0},        {0, 0, 1, 0},
                                       {0, 0, 0, 1},   {.5, .5, 0, 0},      {.5, 0, .5, 0},
                                       {.5, 0, 0, .5}, {0, .5, .5, 0},      {0, .5, 0, .5},
                                       {0, 0, .5, .5}, {.25, .25, .25, .25}};
  for (const auto& l : kNodes)
    if (!(jacobian(c, m, l) > 0)) return false;
  return true;
}

}  // namespace cvtmesh
