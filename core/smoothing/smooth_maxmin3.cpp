#include "core/smoothing/smooth_maxmin3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/geometry/vec3.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/quality.h"
#include "core/smoothing/maxmin_ascent_step.h"

namespace cvtmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDeg = 180.0 / 3.14159265358979323846;
constexpr int kNbFn = 7;  // per tet: Q and the six dihedral angles (scaled)

const int* tet_of(const TetMesh& mesh, int t) {
  return &mesh.tets[4 * static_cast<std::size_t>(t)];
}

double quality_of(const TetMesh& mesh, int t, Measure m) {
  const int* v = tet_of(mesh, t);
  return tet_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]), m);
}

// The smooth functions of tet t (at the current coordinates): Q, then the dihedral angles in
// degrees / scale.
std::array<double, kNbFn> tet_functions(const TetMesh& mesh, int t, double scale) {
  const int* v = tet_of(mesh, t);
  const double *a = mesh.point(v[0]), *b = mesh.point(v[1]), *c = mesh.point(v[2]),
               *d = mesh.point(v[3]);
  std::array<double, kNbFn> f;
  f[0] = tet_quality(a, b, c, d, Measure::kQ);
  const auto ang = tet_dihedral_angles(a, b, c, d);
  for (int e = 0; e < 6; ++e) f[1 + e] = ang[e] * kDeg / scale;
  return f;
}

struct StarValues {
  double objective = kInf;
  bool valid = true;
};

// Exact validity and the objective (from the canonical tet_quality values) of the star of a
// vertex; with `lowest` (two values per tet: Q, min dihedral angle), also invalid when a tet
// falls below them.
StarValues star_values(const TetMesh& mesh, const int* begin, const int* end, double angle_scale,
                       double* q, double* a, const double* lowest = nullptr) {
  StarValues s;
  for (const int* t = begin; t != end; ++t) {
    const int* v = tet_of(mesh, *t);
    const std::size_t i = static_cast<std::size_t>(t - begin);
    if (orient3d(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])) <= 0) {
      s.valid = false;
      return s;
    }
    q[i] = quality_of(mesh, *t, Measure::kQ);
    a[i] = quality_of(mesh, *t, Measure::kMinAngle);
    if (lowest && (q[i] < lowest[2 * i] || a[i] < lowest[2 * i + 1])) {
      s.valid = false;
      return s;
    }
    s.objective =
        std::min(s.objective, angle_scale > 0 ? std::min(q[i], a[i] / angle_scale) : q[i]);
  }
  return s;
}

}  // namespace

MaxMinStats smooth_maxmin3(TetMesh& mesh, const MaxMinOptions& o) {
  if (o.passes < 0 || o.max_steps < 0 || o.max_halvings < 0)
    throw std::invalid_argument("smooth_maxmin3: passes, max_steps and max_halvings must be >= 0");
  const int nt = mesh.nb_tets();
  const VertexTets star = vertex_tets(mesh);
  std::vector<double> tq(static_cast<std::size_t>(nt), kInf), ta(tq.size(), kInf);
  auto refresh = [&](int t) {
    tq[t] = quality_of(mesh, t, Measure::kQ);
    ta[t] = quality_of(mesh, t, Measure::kMinAngle);
  };
#pragma omp parallel for schedule(static, 1024) if (nt > 1024)
  for (int t = 0; t < nt; ++t)
    if (tet_of(mesh, t)[0] >= 0) refresh(t);
  MaxMinStats stats;
  auto global_min = [&](const std::vector<double>& x) {
    return nt ? *std::min_element(x.begin(), x.end()) : 0.0;
  };
  stats.q_min_before = global_min(tq);
  stats.angle_min_before = global_min(ta);
  const double q_floor = std::max(o.q_floor, stats.q_min_before);
  const double angle_floor = std::max(o.angle_floor, stats.angle_min_before);
  auto objective_of = [&](int t) {
    return o.angle_scale > 0 ? std::min(tq[t], ta[t] / o.angle_scale) : tq[t];
  };

  std::vector<std::pair<double, int>> poor;
  std::vector<char> done(static_cast<std::size_t>(mesh.nb_vertices()), 0);
  std::vector<std::array<double, kNbFn>> fv;
  std::vector<std::array<Vec3, kNbFn>> fg;
  std::vector<std::pair<double, Vec3>> cand;
  const double scale = o.angle_scale > 0 ? o.angle_scale : 60;  // of the angles' functions
  std::vector<double> sq, sa, lowest;
  // The nodal sums of the time-step guard, updated after each accepted vertex.
  VertexTimeSteps dt_steps;
  if (o.dt_guard.on) dt_steps = vertex_time_steps(mesh);
  VertexStepChange dt_before, dt_after;
  for (int pass = 0; pass < o.passes; ++pass) {
    ++stats.passes;
    poor.clear();
    for (int t = 0; t < nt; ++t)
      if (tet_of(mesh, t)[0] >= 0 && (tq[t] < o.q_below || ta[t] < o.angle_below) &&
          (!o.only_tets || (*o.only_tets)[t]))
        poor.push_back({objective_of(t), t});
    std::sort(poor.begin(), poor.end());
    std::fill(done.begin(), done.end(), 0);
    long moved_this_pass = 0;
    for (const auto& [unused, t] : poor) {
      for (int k = 0; k < 4; ++k) {
        const int v = tet_of(mesh, t)[k];
        if (done[v] || mesh.vclass[v].dim < 3) continue;
        done[v] = 1;
        ++stats.nb_tried;
        const int *b = star.begin_of(v), *e = star.end_of(v);
        const int n = static_cast<int>(e - b);
        double* P = mesh.point(v);
        const Vec3 start = vec3(P);
        // Finite-difference step: a small fraction of the shortest edge at v.
        const double lmin = shortest_star_edge(mesh, b, e, v);
        const double h = 1e-6 * lmin;
        sq.resize(n);
        sa.resize(n);
        lowest.resize(2 * static_cast<std::size_t>(n));
        StarValues cur = star_values(mesh, b, e, o.angle_scale, sq.data(), sa.data());
        if (!cur.valid) continue;  // cannot happen on a valid mesh; leave such a vertex alone
        const double start_objective = cur.objective;
        // The guards: a tet at or above a floor stays there; one below it stays above the star's
        // minimum now (in each measure).
        const double star_q = *std::min_element(sq.begin(), sq.end());
        const double star_a = *std::min_element(sa.begin(), sa.end());
        for (int i = 0; i < n; ++i) {
          lowest[2 * i] = sq[i] >= q_floor ? q_floor : star_q;
          lowest[2 * i + 1] = sa[i] >= angle_floor ? angle_floor : star_a;
        }
        const double star_dt = o.dt_guard.on ? min_time_step(mesh, b, e) : 0;
        if (o.dt_guard.on) {
          dt_before.clear();
          for (const int* s = b; s != e; ++s) dt_before.add(mesh, tet_of(mesh, *s), -1);
        }
        // The nodal guard of the current position (the star's tets at P).
        auto nodal_ok = [&] {
          dt_after = dt_before;
          for (const int* s = b; s != e; ++s) dt_after.add(mesh, tet_of(mesh, *s), +1);
          return dt_after.allows(o.dt_guard, dt_steps);
        };
        bool moved = false;
        for (int step = 0; step < o.max_steps; ++step) {
          // Values and gradients of every function of the star.
          fv.resize(n);
          fg.resize(n);
          for (int i = 0; i < n; ++i) fv[i] = tet_functions(mesh, b[i], scale);
          for (int c = 0; c < 3; ++c) {
            const double x0 = P[c];
            for (int i = 0; i < n; ++i) {
              P[c] = x0 + h;
              const auto fp = tet_functions(mesh, b[i], scale);
              P[c] = x0 - h;
              const auto fm = tet_functions(mesh, b[i], scale);
              for (int j = 0; j < kNbFn; ++j) fg[i][j][c] = (fp[j] - fm[j]) / (2 * h);
            }
            P[c] = x0;
          }
          // The candidates: the objective's functions (Q, and the angles if angle_scale > 0),
          // then the guards as functions: a value's margin above its lower bound, shifted by the
          // objective, so that a guard at its bound is as active as the minimum (the ascent
          // then slides along it instead of stopping).
          cand.clear();
          double fmin = kInf;
          for (int i = 0; i < n; ++i)
            for (int j = 0; j < (o.angle_scale > 0 ? kNbFn : 1); ++j) {
              cand.push_back({fv[i][j], fg[i][j]});
              fmin = std::min(fmin, fv[i][j]);
            }
          for (int i = 0; i < n; ++i)
            for (int j = 0; j < kNbFn; ++j) {
              const double low = j == 0 ? lowest[2 * i] : lowest[2 * i + 1] / scale;
              cand.push_back({fv[i][j] - low + fmin, fg[i][j]});
            }
          // The common ascent direction, at most a fifth of the shortest edge.
          const AscentStep ascent = maxmin_ascent_step(cand, fmin, 0.2 * lmin);
          if (!ascent.ok) break;
          const Vec3& d = ascent.direction;
          double alpha = ascent.alpha;
          bool accepted = false;
          const Vec3 here = vec3(P);
          for (int halving = 0; halving <= o.max_halvings && !accepted; ++halving) {
            for (int c = 0; c < 3; ++c) P[c] = here[c] + alpha * d[c];
            const StarValues next =
                star_values(mesh, b, e, o.angle_scale, sq.data(), sa.data(), lowest.data());
            if (next.valid && next.objective > cur.objective &&
                (!o.dt_guard.on ||
                 (time_step_allows(o.dt_guard, star_dt, min_time_step(mesh, b, e)) &&
                  nodal_ok()))) {
              accepted = true;
              cur = next;
            } else {
              alpha *= 0.5;
            }
          }
          if (!accepted) {
            for (int c = 0; c < 3; ++c) P[c] = here[c];
            break;
          }
          ++stats.nb_steps;
          moved = true;
        }
        if (moved && cur.objective < start_objective + o.min_gain) moved = false;
        if (moved && o.dt_guard.on) {
          nodal_ok();  // the change at the final position
          dt_after.apply(dt_steps);
        }
        if (moved) {
          ++stats.nb_moved;
          ++moved_this_pass;
          for (const int* s = b; s != e; ++s) refresh(*s);
        } else {
          for (int c = 0; c < 3; ++c) P[c] = start[c];
        }
      }
    }
    if (moved_this_pass == 0) break;
  }
  stats.q_min_after = global_min(tq);
  stats.angle_min_after = global_min(ta);
  return stats;
}

}  // namespace cvtmesh
