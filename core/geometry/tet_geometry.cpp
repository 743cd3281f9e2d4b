#include "core/geometry/tet_geometry.h"

#include <algorithm>
#include <cmath>

namespace cvtmesh {

double tet_volume(const double* a, const double* b, const double* c, const double* d) {
  return dot(sub(b, a), cross(sub(c, a), sub(d, a))) / 6.0;
}

Vec3 tet_circumcenter(const double* a, const double* b, const double* c, const double* d) {
  const Vec3 u = sub(b, a), v = sub(c, a), w = sub(d, a);
  const double det = 2.0 * dot(u, cross(v, w));
  if (det == 0.0)
    return {(a[0] + b[0] + c[0] + d[0]) / 4, (a[1] + b[1] + c[1] + d[1]) / 4,
            (a[2] + b[2] + c[2] + d[2]) / 4};
  const Vec3 r = (norm2(u) * cross(v, w) + norm2(v) * cross(w, u)) + norm2(w) * cross(u, v);
  return {a[0] + r[0] / det, a[1] + r[1] / det, a[2] + r[2] / det};
}

double tet_circumradius(const double* a, const double* b, const double* c, const double* d) {
  const Vec3 cc = tet_circumcenter(a, b, c, d);
  return std::sqrt(dist2(cc.data(), a));
}

double tet_inradius(const double* a, const double* b, const double* c, const double* d) {
  const double area =
      tri_area3d(b, c, d) + tri_area3d(a, c, d) + tri_area3d(a, b, d) + tri_area3d(a, b, c);
  if (area == 0.0) return 0.0;
  return 3.0 * std::fabs(tet_volume(a, b, c, d)) / area;
}

std::array<double, 6> tet_dihedral_cosines(const double* a, const double* b, const double* c,
                                           const double* d) {
  const double* p[4] = {a, b, c, d};
  // Outward (unnormalised) face normals, face f opposite vertex f.
  static const int F[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  Vec3 n[4];
  for (int f = 0; f < 4; ++f) {
    n[f] = cross(sub(p[F[f][1]], p[F[f][0]]), sub(p[F[f][2]], p[F[f][0]]));
    const double l = norm(n[f]);
    if (l > 0) n[f] = (1.0 / l) * n[f];
  }
  // The edge (i,j) is shared by the faces opposite the two other vertices k,l; the interior
  // dihedral angle is pi minus the angle between their outward normals.
  static const int E[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  std::array<double, 6> cs{};
  for (int e = 0; e < 6; ++e) {
    int k = -1, l = -1;
    for (int v = 0; v < 4; ++v)
      if (v != E[e][0] && v != E[e][1]) (k < 0 ? k : l) = v;
    cs[e] = std::clamp(-dot(n[k], n[l]), -1.0, 1.0);
  }
  return cs;
}

std::array<double, 6> tet_dihedral_angles(const double* a, const double* b, const double* c,
                                          const double* d) {
  std::array<double, 6> ang = tet_dihedral_cosines(a, b, c, d);
  for (double& x : ang) x = std::acos(x);
  // For an inverted tet the outward normals point inwards; report the supplementary sense
  // consistently by keeping the same formula (callers check the volume sign).
  return ang;
}

double tet_sum_sq_edges(const double* a, const double* b, const double* c, const double* d) {
  return dist2(a, b) + dist2(a, c) + dist2(a, d) + dist2(b, c) + dist2(b, d) + dist2(c, d);
}

double tri_area2d(const double* a, const double* b, const double* c) {
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

double tri_area3d(const double* a, const double* b, const double* c) {
  return 0.5 * norm(cross(sub(b, a), sub(c, a)));
}

std::array<double, 3> tri_angles(const double* a, const double* b, const double* c, int dim) {
  const double* p[3] = {a, b, c};
  std::array<double, 3> ang{};
  for (int i = 0; i < 3; ++i) {
    const double* o = p[i];
    const double* q = p[(i + 1) % 3];
    const double* r = p[(i + 2) % 3];
    double u[3] = {0, 0, 0}, v[3] = {0, 0, 0};
    for (int k = 0; k < dim; ++k) {
      u[k] = q[k] - o[k];
      v[k] = r[k] - o[k];
    }
    const double nu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const double nv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (nu == 0 || nv == 0) {
      ang[i] = 0;
      continue;
    }
    const double cs = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / (nu * nv);
    ang[i] = std::acos(std::clamp(cs, -1.0, 1.0));
  }
  return ang;
}

std::array<double, 2> tri_circumcenter2d(const double* a, const double* b, const double* c) {
  const double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
  const double d = 2.0 * (bx * cy - by * cx);
  if (d == 0.0) return {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3};
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return {a[0] + (cy * b2 - by * c2) / d, a[1] + (bx * c2 - cx * b2) / d};
}

Vec3 tri_circumcenter3d(const double* a, const double* b, const double* c) {
  const Vec3 u = sub(b, a), v = sub(c, a);
  const Vec3 w = cross(u, v);
  const double d = 2.0 * norm2(w);
  if (d == 0.0)
    return {(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
  const Vec3 r = (1.0 / d) * (norm2(u) * cross(v, w) + norm2(v) * cross(w, u));
  return {a[0] + r[0], a[1] + r[1], a[2] + r[2]};
}

}  // namespace cvtmesh
