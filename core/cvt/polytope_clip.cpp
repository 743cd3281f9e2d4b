#include "core/cvt/polytope_clip.h"

#include <algorithm>
#include <cmath>

namespace cvtmesh {

void tet_polytope(const double* p0, const double* p1, const double* p2, const double* p3,
                  Polytope& p) {
  const Vec3 v[4] = {vec3(p0), vec3(p1), vec3(p2), vec3(p3)};
  static const int F[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  p.clear();
  for (int f = 0; f < 4; ++f) {
    for (int k = 0; k < 3; ++k) p.pts.push_back(v[F[f][k]]);
    p.face_start.push_back(static_cast<int>(p.pts.size()));
    p.face_id.push_back(f);
  }
}

namespace {

// A cheap monotone stand-in for atan2 (the "diamond angle"), in [0, 4).
inline double pseudo_angle(double y, double x) {
  const double s = std::fabs(x) + std::fabs(y);
  if (s == 0) return 0;
  const double r = y / s;
  return x >= 0 ? (y >= 0 ? r : 4 + r) : 2 - r;
}

}  // namespace

bool clip_polytope(Polytope& p, const Vec3& n, double d, int id, double eps, Polytope& out) {
  const double nn = norm(n);
  if (nn == 0) return true;
  const double tol = eps * nn;
  bool any_out = false, any_in = false;
  for (const Vec3& x : p.pts) {
    const double s = dot(n, x) - d;
    any_out |= s > tol;
    any_in |= s < -tol;
  }
  if (!any_out) return true;
  if (!any_in) {
    p.clear();
    return false;
  }
  out.clear();
  // Cap points collected in a small static-size buffer (a convex cap of a cell has few vertices).
  thread_local std::vector<Vec3> cap;
  cap.clear();
  for (int f = 0; f < p.nb_faces(); ++f) {
    const int b0 = p.face_start[f], b1 = p.face_start[f + 1], m = b1 - b0;
    const std::size_t start = out.pts.size();
    for (int i = 0; i < m; ++i) {
      const Vec3& a = p.pts[b0 + i];
      const Vec3& b = p.pts[b0 + (i + 1) % m];
      const double sa = dot(n, a) - d, sb = dot(n, b) - d;
      if (sa <= tol) {
        out.pts.push_back(a);
        if (sa >= -tol) cap.push_back(a);
      }
      if ((sa < -tol && sb > tol) || (sa > tol && sb < -tol)) {
        const double t = sa / (sa - sb);
        const Vec3 x = a + t * (b - a);
        out.pts.push_back(x);
        cap.push_back(x);
      }
    }
    if (out.pts.size() - start >= 3) {
      out.face_start.push_back(static_cast<int>(out.pts.size()));
      out.face_id.push_back(p.face_id[f]);
    } else {
      out.pts.resize(start);
    }
  }
  // The cap: crossing points, deduplicated, sorted by angle around their mean in the plane.
  const double dup2 = (tol / nn) * (tol / nn) * 4 + 1e-300;
  std::size_t nu = 0;
  for (std::size_t i = 0; i < cap.size(); ++i) {
    bool dup = false;
    for (std::size_t j = 0; j < nu && !dup; ++j) dup = norm2(cap[i] - cap[j]) <= dup2;
    if (!dup) cap[nu++] = cap[i];
  }
  cap.resize(nu);
  if (nu >= 3) {
    Vec3 c{0, 0, 0};
    for (const Vec3& x : cap) c = c + x;
    c = (1.0 / static_cast<double>(nu)) * c;
    const Vec3 nz = (1.0 / nn) * n;
    Vec3 ref = cap[0] - c;
    ref = ref - dot(ref, nz) * nz;
    const double lr = norm(ref);
    if (lr > 0) {
      ref = (1.0 / lr) * ref;
      const Vec3 ortho = cross(nz, ref);
      thread_local std::vector<std::pair<double, int>> ang;
      ang.clear();
      for (std::size_t i = 0; i < nu; ++i) {
        const Vec3 r = cap[i] - c;
        ang.push_back({pseudo_angle(dot(r, ortho), dot(r, ref)), static_cast<int>(i)});
      }
      std::sort(ang.begin(), ang.end());
      for (const auto& [a, i] : ang) out.pts.push_back(cap[i]);
      out.face_start.push_back(static_cast<int>(out.pts.size()));
      out.face_id.push_back(id);
    }
  }
  std::swap(p, out);
  return p.nb_faces() >= 4;
}

void Moments::add(const Moments& o) {
  m0 += o.m0;
  m1 = m1 + o.m1;
  for (int i = 0; i < 9; ++i) m2[i] += o.m2[i];
}

Moments polytope_moments(const Polytope& p, const Vec3& z) {
  Moments M;
  if (p.pts.empty()) return M;
  Vec3 c{0, 0, 0};
  for (const Vec3& x : p.pts) c = c + (x - z);
  c = (1.0 / static_cast<double>(p.pts.size())) * c;
  double s2[9] = {0};
  for (int f = 0; f < p.nb_faces(); ++f) {
    const int b0 = p.face_start[f], b1 = p.face_start[f + 1];
    const Vec3 a = p.pts[b0] - z;
    for (int i = b0 + 1; i + 1 < b1; ++i) {
      const Vec3 b = p.pts[i] - z, e = p.pts[i + 1] - z;
      const double vol = std::fabs(dot(a - c, cross(b - c, e - c))) / 6.0;
      if (vol == 0) continue;
      const Vec3 s = ((c + a) + b) + e;
      M.m0 += vol;
      M.m1 = M.m1 + (vol / 4.0) * s;
      // int x x^T over a tet = V/20 (sum p p^T + s s^T).
      const double w = vol / 20.0;
      for (int r = 0; r < 3; ++r)
        for (int q = r; q < 3; ++q)
          s2[3 * r + q] +=
              w * (s[r] * s[q] + c[r] * c[q] + a[r] * a[q] + b[r] * b[q] + e[r] * e[q]);
    }
  }
  for (int r = 0; r < 3; ++r)
    for (int q = 0; q < 3; ++q) M.m2[3 * r + q] = r <= q ? s2[3 * r + q] : s2[3 * q + r];
  return M;
}

double face_area(const Polytope& p, int id) {
  double a = 0;
  for (int f = 0; f < p.nb_faces(); ++f) {
    if (p.face_id[f] != id) continue;
    const int b0 = p.face_start[f], b1 = p.face_start[f + 1];
    Vec3 s{0, 0, 0};
    for (int i = b0 + 1; i + 1 < b1; ++i)
      s = s + cross(p.pts[i] - p.pts[b0], p.pts[i + 1] - p.pts[b0]);
    a += 0.5 * norm(s);
  }
  return a;
}

}  // namespace cvtmesh
