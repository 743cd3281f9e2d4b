#include "core/cvt/polytope_clip.h"

#include <algorithm>
#include <cmath>

namespace cvtmesh {

Polytope tet_polytope(const double* p0, const double* p1, const double* p2, const double* p3) {
  const Vec3 v[4] = {vec3(p0), vec3(p1), vec3(p2), vec3(p3)};
  static const int F[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  Polytope p;
  for (int f = 0; f < 4; ++f) {
    p.faces.push_back({v[F[f][0]], v[F[f][1]], v[F[f][2]]});
    p.face_id.push_back(f);
  }
  return p;
}

bool clip_polytope(Polytope& p, const Vec3& n, double d, int id, double eps) {
  const double nn = norm(n);
  if (nn == 0) return true;
  const double tol = eps * nn;
  // Quick accept / reject on the vertices.
  bool any_out = false, any_in = false;
  for (const auto& f : p.faces)
    for (const Vec3& x : f) {
      const double s = dot(n, x) - d;
      if (s > tol) any_out = true;
      if (s < -tol) any_in = true;
    }
  if (!any_out) return true;
  if (!any_in) {
    p.faces.clear();
    p.face_id.clear();
    return false;
  }
  std::vector<std::vector<Vec3>> faces;
  std::vector<int> ids;
  std::vector<Vec3> cap;
  for (std::size_t k = 0; k < p.faces.size(); ++k) {
    const auto& poly = p.faces[k];
    std::vector<Vec3> out;
    const std::size_t m = poly.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Vec3& a = poly[i];
      const Vec3& b = poly[(i + 1) % m];
      const double sa = dot(n, a) - d, sb = dot(n, b) - d;
      const bool ina = sa <= tol, inb = sb <= tol;
      if (ina) out.push_back(a);
      if (ina && std::fabs(sa) <= tol) cap.push_back(a);
      if ((sa < -tol && sb > tol) || (sa > tol && sb < -tol)) {
        const double t = sa / (sa - sb);
        const Vec3 x = a + t * (b - a);
        out.push_back(x);
        cap.push_back(x);
      }
    }
    if (out.size() >= 3) {
      faces.push_back(std::move(out));
      ids.push_back(p.face_id[k]);
    }
  }
  // The cap: the crossing points, deduplicated, sorted by angle around their mean in the plane.
  std::vector<Vec3> uniq;
  for (const Vec3& x : cap) {
    bool dup = false;
    for (const Vec3& y : uniq)
      if (norm2(x - y) <= tol * tol / (nn * nn) + 1e-300) {
        dup = true;
        break;
      }
    if (!dup) uniq.push_back(x);
  }
  if (uniq.size() >= 3) {
    Vec3 c{0, 0, 0};
    for (const Vec3& x : uniq) c = c + x;
    c = (1.0 / static_cast<double>(uniq.size())) * c;
    const Vec3 nu = (1.0 / nn) * n;
    Vec3 ref = uniq[0] - c;
    ref = ref - dot(ref, nu) * nu;
    const double lr = norm(ref);
    if (lr > 0) {
      ref = (1.0 / lr) * ref;
      const Vec3 ortho = cross(nu, ref);
      std::vector<std::pair<double, Vec3>> ang;
      for (const Vec3& x : uniq) {
        const Vec3 r = x - c;
        ang.push_back({std::atan2(dot(r, ortho), dot(r, ref)), x});
      }
      std::sort(ang.begin(), ang.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      std::vector<Vec3> poly;
      for (const auto& [a, x] : ang) poly.push_back(x);
      faces.push_back(std::move(poly));
      ids.push_back(id);
    }
  }
  p.faces = std::move(faces);
  p.face_id = std::move(ids);
  return p.faces.size() >= 4;
}

void Moments::add(const Moments& o) {
  m0 += o.m0;
  m1 = m1 + o.m1;
  for (int i = 0; i < 9; ++i) m2[i] += o.m2[i];
}

Moments polytope_moments(const Polytope& p, const Vec3& z) {
  Moments M;
  if (p.faces.empty()) return M;
  // Apex: the mean of the vertices (inside the convex polytope), relative to z.
  Vec3 c{0, 0, 0};
  std::size_t n = 0;
  for (const auto& f : p.faces)
    for (const Vec3& x : f) {
      c = c + (x - z);
      ++n;
    }
  c = (1.0 / static_cast<double>(n)) * c;
  for (const auto& f : p.faces) {
    const Vec3 a = f[0] - z;
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      const Vec3 b = f[i] - z, e = f[i + 1] - z;
      const double vol = std::fabs(dot(a - c, cross(b - c, e - c))) / 6.0;
      if (vol == 0) continue;
      const Vec3 s = ((c + a) + b) + e;
      M.m0 += vol;
      M.m1 = M.m1 + (vol / 4.0) * s;
      // int x x^T over a tet = V/20 (sum p p^T + s s^T).
      const Vec3* pts[4] = {&c, &a, &b, &e};
      for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 3; ++q) {
          double acc = s[r] * s[q];
          for (const Vec3* pp : pts) acc += (*pp)[r] * (*pp)[q];
          M.m2[3 * r + q] += vol / 20.0 * acc;
        }
    }
  }
  return M;
}

double face_area(const Polytope& p, int id) {
  double a = 0;
  for (std::size_t k = 0; k < p.faces.size(); ++k) {
    if (p.face_id[k] != id) continue;
    const auto& f = p.faces[k];
    Vec3 s{0, 0, 0};
    for (std::size_t i = 1; i + 1 < f.size(); ++i) s = s + cross(f[i] - f[0], f[i + 1] - f[0]);
    a += 0.5 * norm(s);
  }
  return a;
}

}  // namespace cvtmesh
