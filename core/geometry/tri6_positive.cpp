#include "core/geometry/tri6_positive.h"

#include "core/geometry/predicates.h"

namespace cvtmesh {

const int kTri6Edge[3][2] = {{0, 1}, {1, 2}, {2, 0}};

namespace {

// The Jacobian determinant of X(xi, eta) = sum_i x_i l_i (2 l_i - 1) + 4 (m01 l0 l1 + m12 l1 l2
// + m20 l2 l0), l0 = 1 - xi - eta, l1 = xi, l2 = eta, as a quadratic
// J = k[0] + k[1] xi + k[2] eta + k[3] xi^2 + k[4] xi eta + k[5] eta^2.
struct Jacobian {
  double k[6];
  double at(double xi, double eta) const {
    return k[0] + k[1] * xi + k[2] * eta + k[3] * xi * xi + k[4] * xi * eta + k[5] * eta * eta;
  }
};

// x[6][2]: corners 0, 1, 2 then m01, m12, m20, relative to corner 0.
Jacobian jacobian(const double x[6][2]) {
  // dX/dxi and dX/deta at the barycentric point l (both linear in xi, eta).
  auto derivatives = [&](double xi, double eta, double a[2], double b[2]) {
    const double l0 = 1 - xi - eta, l1 = xi, l2 = eta;
    for (int d = 0; d < 2; ++d) {
      const double x0 = x[0][d], x1 = x[1][d], x2 = x[2][d];
      const double m01 = x[3][d], m12 = x[4][d], m20 = x[5][d];
      a[d] = -x0 * (4 * l0 - 1) + x1 * (4 * l1 - 1) + 4 * m01 * (l0 - l1) + 4 * (m12 - m20) * l2;
      b[d] = -x0 * (4 * l0 - 1) + x2 * (4 * l2 - 1) + 4 * m20 * (l0 - l2) + 4 * (m12 - m01) * l1;
    }
  };
  double a0[2], b0[2], a1[2], b1[2], a2[2], b2[2];
  derivatives(0, 0, a0, b0);
  derivatives(1, 0, a1, b1);
  derivatives(0, 1, a2, b2);
  for (int d = 0; d < 2; ++d) {
    a1[d] -= a0[d];
    b1[d] -= b0[d];
    a2[d] -= a0[d];
    b2[d] -= b0[d];
  }
  // J = (a0 + xi a1 + eta a2) x (b0 + xi b1 + eta b2).
  auto cross = [](const double* u, const double* v) { return u[0] * v[1] - u[1] * v[0]; };
  Jacobian j;
  j.k[0] = cross(a0, b0);
  j.k[1] = cross(a1, b0) + cross(a0, b1);
  j.k[2] = cross(a2, b0) + cross(a0, b2);
  j.k[3] = cross(a1, b1);
  j.k[4] = cross(a1, b2) + cross(a2, b1);
  j.k[5] = cross(a2, b2);
  return j;
}

// The smallest value of J on the reference triangle: at a corner, at the critical point of an
// edge, or at the interior critical point.
double minimum(const Jacobian& j) {
  double lo = j.at(0, 0);
  auto take = [&](double xi, double eta) {
    const double v = j.at(xi, eta);
    if (v < lo) lo = v;
  };
  take(1, 0);
  take(0, 1);
  // Edges p(t) = p + t (q - p): J(p(t)) = u t^2 + v t + w; its critical point t = -v / (2u).
  static const double kEdge[3][4] = {{0, 0, 1, 0}, {1, 0, 0, 1}, {0, 1, 0, 0}};
  for (const auto& e : kEdge) {
    const double w = j.at(e[0], e[1]), h = j.at(0.5 * (e[0] + e[2]), 0.5 * (e[1] + e[3]));
    const double q = j.at(e[2], e[3]);
    const double u = 2 * (w - 2 * h + q), v = q - w - u;
    if (u > 0) {
      const double t = -v / (2 * u);
      if (t > 0 && t < 1) take(e[0] + t * (e[2] - e[0]), e[1] + t * (e[3] - e[1]));
    }
  }
  // Interior: grad J = 0, [2 k3, k4; k4, 2 k5] (xi, eta) = -(k1, k2).
  const double det = 4 * j.k[3] * j.k[5] - j.k[4] * j.k[4];
  if (det != 0) {
    const double xi = (-2 * j.k[5] * j.k[1] + j.k[4] * j.k[2]) / det;
    const double eta = (-2 * j.k[3] * j.k[2] + j.k[4] * j.k[1]) / det;
    if (xi > 0 && eta > 0 && xi + eta < 1) take(xi, eta);
  }
  return lo;
}

}  // namespace

bool tri6_positive(const double* const c[3], const double* const m[3]) {
  // Straight: the map is affine, its Jacobian the corner triangle's orientation.
  bool straight = true;
  for (int k = 0; k < 3 && straight; ++k)
    for (int d = 0; d < 2; ++d)
      straight &= m[k][d] == 0.5 * (c[kTri6Edge[k][0]][d] + c[kTri6Edge[k][1]][d]);
  if (straight) return orient2d(c[0], c[1], c[2]) > 0;
  // The 4 sub-triangles of the node lattice, each with the parent's orientation.
  const double* const m01 = m[0];
  const double* const m12 = m[1];
  const double* const m20 = m[2];
  const double* const sub[4][3] = {
      {c[0], m01, m20}, {m01, c[1], m12}, {m20, m12, c[2]}, {m01, m12, m20}};
  for (const auto& t : sub)
    if (!(orient2d(t[0], t[1], t[2]) > 0)) return false;
  // The Jacobian on coordinates relative to corner 0 (fewer cancellations far from the origin).
  double x[6][2];
  const double* const nodes[6] = {c[0], c[1], c[2], m01, m12, m20};
  for (int i = 0; i < 6; ++i)
    for (int d = 0; d < 2; ++d) x[i][d] = nodes[i][d] - c[0][d];
  const Jacobian j = jacobian(x);
  static const double kNodes[7][2] = {{0, 0},   {1, 0},  {0, 1},          {.5, 0},
                                      {.5, .5}, {0, .5}, {1. / 3, 1. / 3}};
  for (const auto& p : kNodes)
    if (!(j.at(p[0], p[1]) > 0)) return false;
  return minimum(j) > 0;
}

}  // namespace cvtmesh
