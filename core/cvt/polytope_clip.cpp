#include "core/cvt/polytope_clip.h"

#include <algorithm>
#include <cmath>

namespace cvtmesh {

void tet_polytope(const double* p0, const double* p1, const double* p2, const double* p3,
                  Polytope& p) {
  static const int F[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  p.clear();
  p.vtx = {vec3(p0), vec3(p1), vec3(p2), vec3(p3)};
  for (int f = 0; f < 4; ++f) {
    p.fv.insert(p.fv.end(), F[f], F[f] + 3);
    p.face_start.push_back(static_cast<int>(p.fv.size()));
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

// Fallback for the cap when its edges do not chain into one cycle (points within the tolerance
// of the plane can make the face-by-face edges inconsistent): the cap's vertices sorted by angle
// around their mean in the plane.
void cap_by_angle(const std::vector<int>& on, const Vec3& n, Polytope& out) {
  const std::size_t nu = on.size();
  Vec3 c{0, 0, 0};
  for (int i : on) c = c + out.vtx[i];
  c = (1.0 / static_cast<double>(nu)) * c;
  const Vec3 nz = (1.0 / norm(n)) * n;
  Vec3 ref = out.vtx[on[0]] - c;
  ref = ref - dot(ref, nz) * nz;
  const double lr = norm(ref);
  if (!(lr > 0)) return;
  ref = (1.0 / lr) * ref;
  const Vec3 ortho = cross(nz, ref);
  thread_local std::vector<std::pair<double, int>> ang;
  ang.clear();
  for (int i : on) {
    const Vec3 r = out.vtx[i] - c;
    ang.push_back({pseudo_angle(dot(r, ortho), dot(r, ref)), i});
  }
  std::sort(ang.begin(), ang.end());
  for (const auto& [a, i] : ang) out.fv.push_back(i);
}

}  // namespace

bool clip_polytope(Polytope& p, const Vec3& n, double d, int id, double eps, Polytope& out) {
  const double nn = norm(n);
  if (nn == 0) return true;
  bool changed = false;
  return clip_polytope_tol(p, n, d, id, eps * nn, out, changed);
}

bool clip_polytope_tol(Polytope& p, const Vec3& n, double d, int id, double tol, Polytope& out,
                       bool& changed) {
  changed = false;
  const int nv = static_cast<int>(p.vtx.size());
  std::vector<double>& sd = out.sd;
  sd.resize(nv);
  bool any_out = false, any_in = false;
  for (int i = 0; i < nv; ++i) {
    sd[i] = dot(n, p.vtx[i]) - d;
    any_out |= sd[i] > tol;
    any_in |= sd[i] < -tol;
  }
  if (!any_out) return true;
  changed = true;
  if (!any_in) {
    p.clear();
    return false;
  }
  out.clear();
  // Kept vertices; "next" marks on-plane vertices (-1: on the plane, no cap edge yet; -2: not on).
  std::vector<int>& remap = out.remap;
  std::vector<int>& next = out.next;
  remap.assign(nv, -1);
  next.clear();
  for (int i = 0; i < nv; ++i)
    if (sd[i] <= tol) {
      remap[i] = static_cast<int>(out.vtx.size());
      out.vtx.push_back(p.vtx[i]);
      next.push_back(sd[i] >= -tol ? -1 : -2);
    }
  out.cut.clear();
  // The vertex where edge (a, b) crosses the plane, one per edge whatever the direction.
  auto cut_vertex = [&](int a, int b) {
    const int lo = std::min(a, b), hi = std::max(a, b);
    for (const auto& c : out.cut)
      if (c[0] == lo && c[1] == hi) return c[2];
    const double t = sd[lo] / (sd[lo] - sd[hi]);
    const int k = static_cast<int>(out.vtx.size());
    out.vtx.push_back(p.vtx[lo] + t * (p.vtx[hi] - p.vtx[lo]));
    next.push_back(-1);
    out.cut.push_back({lo, hi, k});
    return k;
  };
  bool chain_ok = true;
  for (int f = 0; f < p.nb_faces(); ++f) {
    const int b0 = p.face_start[f], m = p.face_start[f + 1] - b0;
    const std::size_t start = out.fv.size();
    for (int i = 0; i < m; ++i) {
      const int a = p.fv[b0 + i], b = p.fv[i + 1 == m ? b0 : b0 + i + 1];
      if (remap[a] >= 0) out.fv.push_back(remap[a]);
      if ((sd[a] < -tol && sd[b] > tol) || (sd[a] > tol && sd[b] < -tol))
        out.fv.push_back(cut_vertex(a, b));
    }
    const int k = static_cast<int>(out.fv.size() - start);
    if (k < 3) {
      out.fv.resize(start);
      continue;
    }
    // Edges of the kept face with both ends on the plane bound the cap, which runs along them
    // the other way. A face with every vertex on the plane has no area: dropped.
    int nb_on = 0;
    for (int i = 0; i < k; ++i) nb_on += next[out.fv[start + i]] != -2;
    if (nb_on == k) {
      out.fv.resize(start);
      continue;
    }
    for (int i = 0; i < k; ++i) {
      const int u = out.fv[start + i], w = out.fv[i + 1 == k ? start : start + i + 1];
      if (next[u] == -2 || next[w] == -2) continue;
      if (next[w] >= 0 && next[w] != u) chain_ok = false;
      next[w] = u;
    }
    out.face_start.push_back(static_cast<int>(out.fv.size()));
    out.face_id.push_back(p.face_id[f]);
  }
  // The cap: follow the chain from any on-plane vertex that has an edge.
  thread_local std::vector<int> on;
  on.clear();
  int first = -1, nb_linked = 0;
  for (int i = 0; i < static_cast<int>(next.size()); ++i) {
    if (next[i] == -2) continue;
    if (next[i] >= 0) {
      ++nb_linked;
      if (first < 0) first = i;
    }
  }
  const std::size_t cap_start = out.fv.size();
  if (chain_ok && first >= 0) {
    int u = first, steps = 0;
    do {
      out.fv.push_back(u);
      u = next[u];
      ++steps;
    } while (u >= 0 && u != first && steps <= nb_linked);
    if (u != first || steps != nb_linked) {
      out.fv.resize(cap_start);
      chain_ok = false;
    }
  }
  if (!chain_ok) {
    for (int i = 0; i < static_cast<int>(next.size()); ++i)
      if (next[i] >= 0) on.push_back(i);
    if (on.size() >= 3) cap_by_angle(on, n, out);
  }
  if (out.fv.size() - cap_start >= 3) {
    out.face_start.push_back(static_cast<int>(out.fv.size()));
    out.face_id.push_back(id);
  } else {
    out.fv.resize(cap_start);
  }
  std::swap(p.vtx, out.vtx);
  std::swap(p.fv, out.fv);
  std::swap(p.face_start, out.face_start);
  std::swap(p.face_id, out.face_id);
  return p.nb_faces() >= 4;
}

void Moments::add(const Moments& o) {
  m0 += o.m0;
  m1 = m1 + o.m1;
  for (int i = 0; i < 9; ++i) m2[i] += o.m2[i];
}

Moments polytope_moments(const Polytope& p, const Vec3& z) {
  Moments M;
  if (p.vtx.empty() || p.nb_faces() == 0) return M;
  Vec3 c{0, 0, 0};
  for (const Vec3& x : p.vtx) c = c + (x - z);
  c = (1.0 / static_cast<double>(p.vtx.size())) * c;
  double s2[6] = {0};
  for (int f = 0; f < p.nb_faces(); ++f) {
    const int b0 = p.face_start[f], b1 = p.face_start[f + 1];
    const Vec3 a = p.vtx[p.fv[b0]] - z;
    for (int i = b0 + 1; i + 1 < b1; ++i) {
      const Vec3 b = p.vtx[p.fv[i]] - z, e = p.vtx[p.fv[i + 1]] - z;
      const double vol = std::fabs(dot(a - c, cross(b - c, e - c))) / 6.0;
      if (vol == 0) continue;
      const Vec3 s = ((c + a) + b) + e;
      M.m0 += vol;
      M.m1 = M.m1 + (vol / 4.0) * s;
      // int x x^T over a tet = V/20 (sum p p^T + s s^T).
      const double w = vol / 20.0;
      int k = 0;
      for (int r = 0; r < 3; ++r)
        for (int q = r; q < 3; ++q)
          s2[k++] += w * (s[r] * s[q] + c[r] * c[q] + a[r] * a[q] + b[r] * b[q] + e[r] * e[q]);
    }
  }
  const int idx[3][3] = {{0, 1, 2}, {1, 3, 4}, {2, 4, 5}};
  for (int r = 0; r < 3; ++r)
    for (int q = 0; q < 3; ++q) M.m2[3 * r + q] = s2[idx[r][q]];
  return M;
}

double face_area(const Polytope& p, int id) {
  double a = 0;
  for (int f = 0; f < p.nb_faces(); ++f) {
    if (p.face_id[f] != id) continue;
    const int b0 = p.face_start[f], b1 = p.face_start[f + 1];
    const Vec3& o = p.vtx[p.fv[b0]];
    Vec3 s{0, 0, 0};
    for (int i = b0 + 1; i + 1 < b1; ++i) s = s + cross(p.vtx[p.fv[i]] - o, p.vtx[p.fv[i + 1]] - o);
    a += 0.5 * norm(s);
  }
  return a;
}

}  // namespace cvtmesh
