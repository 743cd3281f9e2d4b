#include "core/smoothing/nelder_mead_vertex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/geometry/vec3.h"
#include "core/quality/element_time_step.h"
#include "core/quality/quality.h"

namespace cvtmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const int* tet_of(const TetMesh& mesh, int t) {
  return &mesh.tets[4 * static_cast<std::size_t>(t)];
}

}  // namespace

NelderMeadVertexResult nelder_mead_vertex(TetMesh& mesh, int v, const int* star, int nb,
                                          const NelderMeadVertexOptions& o) {
  NelderMeadVertexResult r;
  if (nb <= 0) return r;
  double* P = mesh.point(v);
  const Vec3 start = vec3(P);
  // The shortest star edge (the scale of the first simplex).
  double lmin = kInf;
  for (int i = 0; i < nb; ++i) {
    const int* tv = tet_of(mesh, star[i]);
    for (int k = 0; k < 4; ++k)
      if (tv[k] != v) lmin = std::min(lmin, std::sqrt(dist2(P, mesh.point(tv[k]))));
  }
  if (!(lmin > 0) || lmin == kInf) return r;
  // The objective at x: -inf where a tet is flat or inverted; below -1 by the bounds' violation
  // (Q in units of 1, angles of 180 degrees, the time step relative to its floor) outside them;
  // the star's minimum of min(Q, angle / angle_scale) inside. Floating point; the exact check of
  // the orientation at the end.
  auto value = [&](const Vec3& x) {
    for (int c = 0; c < 3; ++c) P[c] = x[c];
    double f = kInf, violation = 0;
    for (int i = 0; i < nb; ++i) {
      const int* tv = tet_of(mesh, star[i]);
      const double *a = mesh.point(tv[0]), *b = mesh.point(tv[1]), *c = mesh.point(tv[2]),
                   *d = mesh.point(tv[3]);
      const std::array<double, 4> m = tet_table_qualities(a, b, c, d);
      if (!(m[0] > 0)) return -kInf;
      violation +=
          std::max(0.0, o.q_floor - m[0]) +
          (std::max(0.0, o.angle_floor - m[2]) + std::max(0.0, m[3] - o.angle_ceiling)) / 180;
      if (o.dt_floor > 0)
        violation += std::max(0.0, o.dt_floor - tet_time_step(a, b, c, d)) / o.dt_floor;
      f = std::min(f, std::min(m[0], m[2] / o.angle_scale));
    }
    return violation > 0 ? -1 - violation : f;
  };
  r.before = value(start);
  r.after = r.before;
  if (r.before == -kInf) {
    for (int c = 0; c < 3; ++c) P[c] = start[c];
    return r;
  }
  // The simplex: the start and a step along each axis.
  std::array<Vec3, 4> x;
  std::array<double, 4> f;
  x[0] = start;
  f[0] = r.before;
  for (int k = 0; k < 3; ++k) {
    x[k + 1] = start;
    x[k + 1][k] += o.initial_size * lmin;
    f[k + 1] = value(x[k + 1]);
  }
  int evaluations = 4;
  while (evaluations < o.max_evaluations) {
    // Best first.
    std::array<int, 4> idx{0, 1, 2, 3};
    std::sort(idx.begin(), idx.end(), [&](int a, int b) { return f[a] > f[b]; });
    std::array<Vec3, 4> xs;
    std::array<double, 4> fs;
    for (int k = 0; k < 4; ++k) {
      xs[k] = x[idx[k]];
      fs[k] = f[idx[k]];
    }
    x = xs;
    f = fs;
    double size = 0;
    for (int k = 1; k < 4; ++k) size = std::max(size, std::sqrt(dist2(x[k].data(), x[0].data())));
    if (size < 1e-9 * lmin) break;
    const Vec3 c = (1.0 / 3) * (x[0] + x[1] + x[2]);
    const Vec3 xr = c + (c - x[3]);
    const double fr = value(xr);
    ++evaluations;
    if (fr > f[0]) {
      const Vec3 xe = c + 2.0 * (c - x[3]);
      const double fe = value(xe);
      ++evaluations;
      if (fe > fr) {
        x[3] = xe;
        f[3] = fe;
      } else {
        x[3] = xr;
        f[3] = fr;
      }
      continue;
    }
    if (fr > f[2]) {
      x[3] = xr;
      f[3] = fr;
      continue;
    }
    // Contraction (outside if the reflection beat the worst, inside otherwise).
    const Vec3 xc = fr > f[3] ? c + 0.5 * (xr - c) : c + 0.5 * (x[3] - c);
    const double fc = value(xc);
    ++evaluations;
    if (fc > std::max(fr, f[3])) {
      x[3] = xc;
      f[3] = fc;
      continue;
    }
    // Shrink towards the best.
    for (int k = 1; k < 4; ++k) {
      x[k] = x[0] + 0.5 * (x[k] - x[0]);
      f[k] = value(x[k]);
    }
    evaluations += 3;
  }
  int best = 0;
  for (int k = 1; k < 4; ++k)
    if (f[k] > f[best]) best = k;
  if (f[best] >= 0 && f[best] > r.before + o.min_gain) {
    // The exact check of the new position.
    for (int c = 0; c < 3; ++c) P[c] = x[best][c];
    bool ok = value(x[best]) == f[best];
    for (int i = 0; i < nb && ok; ++i) {
      const int* tv = tet_of(mesh, star[i]);
      ok = orient3d(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]), mesh.point(tv[3])) > 0;
    }
    if (ok) {
      r.moved = true;
      r.after = f[best];
      return r;
    }
  }
  for (int c = 0; c < 3; ++c) P[c] = start[c];
  return r;
}

}  // namespace cvtmesh
