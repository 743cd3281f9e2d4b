#include "core/smoothing/smooth_min_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/geometry/vec3.h"
#include "core/mesh/vertex_star.h"

namespace cvtmesh {
namespace {

struct StarEval {
  double min_q;
  int worst;  // index in the star list
};

// Minimum quality over the star of v with v placed at x; -inf if a tet would invert (exact test).
StarEval eval_star(const TetMesh& m, const VertexStar& star, int v, const double* x,
                   Measure measure) {
  StarEval e{std::numeric_limits<double>::infinity(), -1};
  for (int i = star.offset[v]; i < star.offset[v + 1]; ++i) {
    const int* tv = &m.tets[4 * star.tet[i]];
    const double* p[4];
    for (int k = 0; k < 4; ++k) p[k] = tv[k] == v ? x : m.point(tv[k]);
    if (orient3d(p[0], p[1], p[2], p[3]) <= 0) return {-std::numeric_limits<double>::infinity(), i};
    const double q = tet_quality(p[0], p[1], p[2], p[3], measure);
    if (q < e.min_q) e = {q, i};
  }
  return e;
}

// Gradient of the quality of star tet i with respect to the position of v (central differences).
Vec3 quality_gradient(const TetMesh& m, const VertexStar& star, int v, int i, const double* x,
                      double h, Measure measure) {
  const int* tv = &m.tets[4 * star.tet[i]];
  Vec3 g{0, 0, 0};
  for (int d = 0; d < 3; ++d) {
    double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
    xp[d] += h;
    xm[d] -= h;
    const double* pp[4];
    const double* pm[4];
    for (int k = 0; k < 4; ++k) {
      pp[k] = tv[k] == v ? xp : m.point(tv[k]);
      pm[k] = tv[k] == v ? xm : m.point(tv[k]);
    }
    g[d] = (tet_quality(pp[0], pp[1], pp[2], pp[3], measure) -
            tet_quality(pm[0], pm[1], pm[2], pm[3], measure)) /
           (2 * h);
  }
  return g;
}

double star_scale(const TetMesh& m, const VertexStar& star, int v) {
  double s = 0;
  int n = 0;
  for (int i = star.offset[v]; i < star.offset[v + 1]; ++i)
    for (int k = 0; k < 4; ++k) {
      const int w = m.tets[4 * star.tet[i] + k];
      if (w != v) s += std::sqrt(dist2(m.point(v), m.point(w))), ++n;
    }
  return n ? s / n : 0;
}

}  // namespace

MinQualitySmoothStats smooth_min_quality(TetMesh& m, const MinQualitySmoothOptions& o) {
  MinQualitySmoothStats st;
  auto global_min = [&] {
    double q = std::numeric_limits<double>::infinity();
    for (int t = 0; t < m.nb_tets(); ++t) {
      const int* v = &m.tets[4 * t];
      if (v[0] < 0) continue;
      q = std::min(
          q, tet_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]), o.measure));
    }
    return q;
  };
  st.min_before = global_min();
  const VertexStar star = build_vertex_star(m);
  for (int pass = 0; pass < o.passes; ++pass) {
    // Free vertices of poor tets, worst first.
    std::vector<std::pair<double, int>> todo;
    std::vector<char> seen(m.nb_vertices(), 0);
    for (int t = 0; t < m.nb_tets(); ++t) {
      const int* v = &m.tets[4 * t];
      if (v[0] < 0) continue;
      const double q =
          tet_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]), o.measure);
      if (q >= o.threshold) continue;
      for (int k = 0; k < 4; ++k)
        if (m.vclass[v[k]].dim == 3 && !seen[v[k]]) {
          seen[v[k]] = 1;
          todo.push_back({q, v[k]});
        }
    }
    std::sort(todo.begin(), todo.end());
    int moved = 0;
    for (const auto& [q0, v] : todo) {
      double x[3] = {m.point(v)[0], m.point(v)[1], m.point(v)[2]};
      StarEval cur = eval_star(m, star, v, x, o.measure);
      const double h = star_scale(m, star, v);
      if (h <= 0 || !std::isfinite(cur.min_q)) continue;
      const double start = cur.min_q;
      double step = 0.1 * h;
      for (int it = 0; it < o.max_steps && step > 1e-4 * h && cur.min_q < o.target; ++it) {
        Vec3 g = quality_gradient(m, star, v, cur.worst, x, 1e-6 * h, o.measure);
        const double gn = norm(g);
        if (gn == 0) break;
        g = (1.0 / gn) * g;
        bool improved = false;
        while (step > 1e-4 * h) {
          const double y[3] = {x[0] + step * g[0], x[1] + step * g[1], x[2] + step * g[2]};
          const StarEval e = eval_star(m, star, v, y, o.measure);
          if (e.min_q > cur.min_q) {
            std::copy(y, y + 3, x);
            cur = e;
            improved = true;
            step *= 1.5;
            break;
          }
          step *= 0.5;
        }
        if (!improved) break;
      }
      if (cur.min_q > start) {
        std::copy(x, x + 3, m.point(v));
        ++moved;
      }
    }
    st.nb_moved += moved;
    if (!moved) break;
  }
  st.min_after = global_min();
  return st;
}

}  // namespace cvtmesh
