#include "core/quality/quality.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/geometry/tet_geometry.h"
#include "core/quality/element_time_step.h"

namespace cvtmesh {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = 180.0 / kPi;

double sgn(double v) {
  return v < 0 ? -1.0 : 1.0;
}

// Gmsh's "ICN" (Plugin(AnalyseMeshQuality), jacobianBasedQuality::minICNMeasure) for a linear
// tet: with J the Jacobian of the map from the ideal (regular) tet, Gmsh evaluates
// 3 det(J)^(2/3) / ||J||_F^2 (qualityMeasuresJacobian.cpp, _computeICN) -- the mean-ratio form,
// not d / (||J||_F ||J^-1||_F). Scale- and rotation-invariant; 1 for the regular tet. Signed by
// det J here (Gmsh reports 0 for an inverted element).
double tet_icn(const double* a, const double* b, const double* c, const double* d) {
  // J = E * R^-1, E = [b-a c-a d-a], R the regular tet of unit edge
  // (0,0,0),(1,0,0),(1/2,sqrt3/2,0),(1/2,sqrt3/6,sqrt(2/3)).
  const double s3 = std::sqrt(3.0), s23 = std::sqrt(2.0 / 3.0);
  const double R[3][3] = {{1, 0.5, 0.5}, {0, s3 / 2, s3 / 6}, {0, 0, s23}};  // columns r1,r2,r3
  // Inverse of the upper-triangular R.
  double Ri[3][3] = {{0}};
  Ri[0][0] = 1 / R[0][0];
  Ri[1][1] = 1 / R[1][1];
  Ri[2][2] = 1 / R[2][2];
  Ri[0][1] = -R[0][1] * Ri[1][1] / R[0][0];
  Ri[1][2] = -R[1][2] * Ri[2][2] / R[1][1];
  Ri[0][2] = -(R[0][1] * Ri[1][2] + R[0][2] * Ri[2][2]) / R[0][0];
  double E[3][3];
  for (int k = 0; k < 3; ++k) {
    E[k][0] = b[k] - a[k];
    E[k][1] = c[k] - a[k];
    E[k][2] = d[k] - a[k];
  }
  double J[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      J[i][j] = 0;
      for (int k = 0; k < 3; ++k) J[i][j] += E[i][k] * Ri[k][j];
    }
  const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                     J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                     J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  if (det == 0.0) return 0.0;
  double f2 = 0;
  for (auto& row : J)
    for (double v : row) f2 += v * v;
  return 3.0 * std::cbrt(det * det) / f2 * sgn(det);
}

double dist2n(const double* a, const double* b, int dim) {
  double s = 0;
  for (int k = 0; k < dim; ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return s;
}

// Signed area: counter-clockwise positive in 2D; always >= 0 in 3D.
double tri_signed_area(const double* a, const double* b, const double* c, int dim) {
  return dim == 2 ? tri_area2d(a, b, c) : tri_area3d(a, b, c);
}

}  // namespace

Measure measure_from_string(const std::string& name) {
  if (name == "q" || name == "Q") return Measure::kQ;
  if (name == "radius-ratio" || name == "gamma") return Measure::kRadiusRatio;
  if (name == "min-angle" || name == "min-dihedral") return Measure::kMinAngle;
  if (name == "max-angle" || name == "max-dihedral") return Measure::kMaxAngle;
  if (name == "icn") return Measure::kGmshIcn;
  if (name == "time-step" || name == "dt") return Measure::kTimeStep;
  throw std::invalid_argument("unknown quality measure '" + name +
                              "' (expected q, radius-ratio, min-angle, max-angle, icn, time-step)");
}

std::string measure_name(Measure m) {
  switch (m) {
    case Measure::kQ:
      return "q";
    case Measure::kRadiusRatio:
      return "radius-ratio";
    case Measure::kMinAngle:
      return "min-angle";
    case Measure::kMaxAngle:
      return "max-angle";
    case Measure::kGmshIcn:
      return "icn";
    case Measure::kTimeStep:
      return "time-step";
  }
  return "?";
}

namespace {

// One value per tet, whatever the order its vertices are listed in: the rounding of a near-flat
// tet's volume and angles depends on that order (a 1e-14 sliver's dihedral angle can come out
// as 0 in one order and 1e-8 in another), and the swaps compare qualities of the same tets seen
// from different edges (a refused cavity must stay refused). The vertices are sorted by their
// coordinates, then the last two exchanged if that was an odd permutation (same orientation).
// Without branches (the same value, NaN included): the comparisons of a tet's points are data
// dependent (canonical_order was 9.5% of the polish's samples at ~1M tets, `perf record` of
// `cvtmesh optimize c1m.msh`; the whole run ~1% faster without the branches).
bool lex_less(const double* p, const double* q) {
  const bool lt0 = p[0] < q[0], gt0 = q[0] < p[0];
  const bool lt1 = p[1] < q[1], gt1 = q[1] < p[1];
  const bool lt2 = p[2] < q[2];
  return lt0 | (!gt0 & (lt1 | (!gt1 & lt2)));
}

// The stable sort by ranks (each point's place = how many points precede it), without moving
// pointers through memory in a data-dependent loop: the same order and parity as an insertion
// sort (its swaps are the strict inversions), at a fraction of the cost (this runs for every
// quality evaluated).
void canonical_order(const double*& a, const double*& b, const double*& c, const double*& d) {
  const double* p[4] = {a, b, c, d};
  int rank[4] = {0, 0, 0, 0};
  int inversions = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const bool inv = lex_less(p[j], p[i]);
      rank[inv ? i : j] += 1;
      inversions += inv;
    }
  const double* q[4];
  for (int i = 0; i < 4; ++i) q[rank[i]] = p[i];
  if (inversions & 1) std::swap(q[2], q[3]);
  a = q[0];
  b = q[1];
  c = q[2];
  d = q[3];
}

double q_of(const double* a, const double* b, const double* c, const double* d, double vol) {
  const double s = tet_sum_sq_edges(a, b, c, d);
  if (s == 0) return 0;
  return 72.0 * std::sqrt(3.0) * vol / (s * std::sqrt(s));
}

double radius_ratio_of(const double* a, const double* b, const double* c, const double* d,
                       double vol) {
  const double r = tet_inradius(a, b, c, d);
  const double R = tet_circumradius(a, b, c, d);
  if (R == 0 || !std::isfinite(R) || vol == 0) return 0;
  return 3.0 * r / R * sgn(vol);
}

// acos decreases: the smallest angle has the largest cosine.
double min_angle_of(const std::array<double, 6>& cs, double vol) {
  const double v = std::acos(*std::max_element(cs.begin(), cs.end())) * kDeg;
  return vol < 0 ? -v : v;
}

double max_angle_of(const std::array<double, 6>& cs) {
  return std::acos(*std::min_element(cs.begin(), cs.end())) * kDeg;
}

}  // namespace

double tet_quality(const double* a, const double* b, const double* c, const double* d, Measure m) {
  canonical_order(a, b, c, d);
  const double vol = tet_volume(a, b, c, d);
  switch (m) {
    case Measure::kQ:
      return q_of(a, b, c, d, vol);
    case Measure::kRadiusRatio:
      return radius_ratio_of(a, b, c, d, vol);
    case Measure::kMinAngle:
      return min_angle_of(tet_dihedral_cosines(a, b, c, d), vol);
    case Measure::kMaxAngle:
      return max_angle_of(tet_dihedral_cosines(a, b, c, d));
    case Measure::kGmshIcn:
      return tet_icn(a, b, c, d);
    case Measure::kTimeStep:
      return tet_time_step(a, b, c, d);
  }
  return 0;
}

std::array<double, 4> tet_table_qualities(const double* a, const double* b, const double* c,
                                          const double* d) {
  canonical_order(a, b, c, d);
  const double vol = tet_volume(a, b, c, d);
  const auto cs = tet_dihedral_cosines(a, b, c, d);
  return {q_of(a, b, c, d, vol), radius_ratio_of(a, b, c, d, vol), min_angle_of(cs, vol),
          max_angle_of(cs)};
}

std::array<double, 2> tri_min_max_angle(const double* a, const double* b, const double* c,
                                        int dim) {
  const double area = tri_signed_area(a, b, c, dim);
  const auto ang = tri_angles(a, b, c, dim);
  const double lo = *std::min_element(ang.begin(), ang.end()) * kDeg;
  return {area < 0 ? -lo : lo, *std::max_element(ang.begin(), ang.end()) * kDeg};
}

double tri_quality(const double* a, const double* b, const double* c, int dim, Measure m) {
  const double area = tri_signed_area(a, b, c, dim);
  switch (m) {
    case Measure::kQ:
    case Measure::kGmshIcn: {  // for linear triangles Gmsh's ICN equals the paper's Q
      const double l2 = dist2n(a, b, dim) + dist2n(b, c, dim) + dist2n(c, a, dim);
      if (l2 == 0) return 0;
      return 4.0 * std::sqrt(3.0) * area / l2;
    }
    case Measure::kRadiusRatio: {
      const double la = std::sqrt(dist2n(b, c, dim)), lb = std::sqrt(dist2n(c, a, dim)),
                   lc = std::sqrt(dist2n(a, b, dim));
      const double s = 0.5 * (la + lb + lc);
      if (s == 0 || area == 0) return 0;
      const double r = std::fabs(area) / s;
      const double R = la * lb * lc / (4.0 * std::fabs(area));
      return 2.0 * r / R * sgn(area);
    }
    case Measure::kMinAngle: {
      const auto ang = tri_angles(a, b, c, dim);
      const double v = *std::min_element(ang.begin(), ang.end()) * kDeg;
      return area < 0 ? -v : v;
    }
    case Measure::kMaxAngle: {
      const auto ang = tri_angles(a, b, c, dim);
      return *std::max_element(ang.begin(), ang.end()) * kDeg;
    }
    case Measure::kTimeStep: {
      if (dim == 2) return tri_time_step(a, b, c);
      // A triangle in space: its time step in its own plane (a 2D frame of the triangle).
      const double ab = std::sqrt(dist2n(a, b, 3));
      if (ab == 0) return 0;
      double u[3], w[3];
      for (int k = 0; k < 3; ++k) {
        u[k] = (b[k] - a[k]) / ab;
        w[k] = c[k] - a[k];
      }
      const double wu = w[0] * u[0] + w[1] * u[1] + w[2] * u[2];
      const double h2 = dist2n(a, c, 3) - wu * wu;
      const double p0[2] = {0, 0}, p1[2] = {ab, 0}, p2[2] = {wu, std::sqrt(std::max(0.0, h2))};
      return tri_time_step(p0, p1, p2);
    }
  }
  return 0;
}

}  // namespace cvtmesh
