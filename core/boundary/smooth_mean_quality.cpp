#include "core/boundary/smooth_mean_quality.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/boundary_move.h"
#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/geometry/vec3.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/quality.h"

namespace cvtmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

const int* tet_of(const TetMesh& m, int t) {
  return &m.tets[4 * static_cast<std::size_t>(t)];
}

double q_of(const TetMesh& m, int t) {
  const int* v = tet_of(m, t);
  return tet_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]), Measure::kQ);
}

double angle_of(const TetMesh& m, int t) {
  const int* v = tet_of(m, t);
  return tet_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]),
                     Measure::kMinAngle);
}

// Whether every dihedral angle of tet t is above the angle whose cosine is cos_low (the cosines
// compared: no acos), with the faces' normals as tet_dihedral_angles takes them.
bool angles_above(const TetMesh& m, int t, double cos_low) {
  const int* v = tet_of(m, t);
  const double* p[4] = {m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])};
  static const int F[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  Vec3 n[4];
  double l[4];
  for (int f = 0; f < 4; ++f) {
    n[f] = cross(sub(p[F[f][1]], p[F[f][0]]), sub(p[F[f][2]], p[F[f][0]]));
    l[f] = norm(n[f]);
    if (!(l[f] > 0)) return false;
  }
  // The angle at the edge shared by faces k and l is pi minus the angle between their outward
  // normals: its cosine is -n_k.n_l / (|n_k| |n_l|).
  for (int k = 0; k < 4; ++k)
    for (int j = k + 1; j < 4; ++j)
      if (-dot(n[k], n[j]) > cos_low * l[k] * l[j]) return false;
  return true;
}

double tri_q_of(const TetMesh& m, int f) {
  const int* v = &m.tris[3 * static_cast<std::size_t>(f)];
  return tri_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), 3, Measure::kQ);
}

}  // namespace

void tet_q_gradient(const double* const p[4], int k, double g[3]) {
  // Q = c V / S^(3/2), V = det(b - a, c - a, d - a) / 6, S = the sum of the squared edge lengths.
  const Vec3 a = vec3(p[0]), b = vec3(p[1]), c = vec3(p[2]), d = vec3(p[3]);
  const Vec3 ab = b - a, ac = c - a, ad = d - a;
  const double vol = dot(cross(ab, ac), ad) / 6;
  double s = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) s += dist2(p[i], p[j]);
  // dV/db, dV/dc, dV/dd; dV/da = -(their sum).
  Vec3 dv[4];
  dv[1] = (1.0 / 6) * cross(ac, ad);
  dv[2] = (1.0 / 6) * cross(ad, ab);
  dv[3] = (1.0 / 6) * cross(ab, ac);
  dv[0] = -1.0 * (dv[1] + dv[2] + dv[3]);
  // dS/dp_k = 2 sum over the other vertices w of (p_k - p_w) = 2 (4 p_k - sum of all).
  const Vec3 sum = a + b + c + d;
  const Vec3 ds = 2.0 * (4.0 * vec3(p[k]) - sum);
  const double cq = 72.0 * std::sqrt(3.0);
  if (!(s > 0)) {
    g[0] = g[1] = g[2] = 0;
    return;
  }
  const double s15 = s * std::sqrt(s);
  for (int i = 0; i < 3; ++i) g[i] = cq * (dv[k][i] / s15 - 1.5 * vol * ds[i] / (s15 * s));
}

MeanQualityStats smooth_mean_quality(TetMesh& mesh, const BoundaryModel& model,
                                     const MeanQualityOptions& o) {
  if (o.passes < 0 || o.max_steps < 0 || o.max_halvings < 0 || !(o.step > 0))
    throw std::invalid_argument(
        "smooth_mean_quality: passes, max_steps, max_halvings must be >= 0 and step > 0");
  MeanQualityStats stats;
  const int nv = mesh.nb_vertices();
  for (int t = 0; t < mesh.nb_tets(); ++t)
    if (tet_of(mesh, t)[0] >= 0) stats.sum_before += q_of(mesh, t);
  stats.sum_after = stats.sum_before;
  const bool boundary = o.boundary && model.geometry;
  // The floors, raised to the mesh's minima at the start (as smooth_maxmin3's): so no move takes
  // a value from above the mesh's minimum to below it, and the minima never fall.
  double q_floor = o.q_floor, angle_floor = o.angle_floor, tri_floor = o.tri_floor;
  {
    double q_min = kInf, a_min = kInf, t_min = kInf;
    for (int t = 0; t < mesh.nb_tets(); ++t)
      if (tet_of(mesh, t)[0] >= 0) {
        q_min = std::min(q_min, q_of(mesh, t));
        a_min = std::min(a_min, angle_of(mesh, t));
      }
    if (boundary)
      for (int f = 0; f < mesh.nb_tris(); ++f) t_min = std::min(t_min, tri_q_of(mesh, f));
    q_floor = std::max(q_floor, q_min);
    angle_floor = std::max(angle_floor, a_min);
    if (t_min < kInf) tri_floor = std::max(tri_floor, t_min);
  }
  const VertexTets star = vertex_tets(mesh);
  const BoundaryFans fans = boundary_fans(mesh);
  VertexTimeSteps dt_steps;
  if (o.dt_guard.on) dt_steps = vertex_time_steps(mesh);
  VertexStepChange dt_change;
  std::vector<double> delta;
  for (int pass = 0; pass < o.passes; ++pass) {
    long moved_this_pass = 0;
    for (int v = 0; v < nv; ++v) {
      const bool interior = mesh.vclass[v].dim == 3;
      if (interior ? !o.interior : !(boundary && model.movable(v))) continue;
      const int *b = star.begin_of(v), *e = star.end_of(v);
      const int n = static_cast<int>(e - b);
      if (n == 0) continue;
      double cur = 0, star_q = kInf, star_a = kInf, fan_q = kInf;
      for (const int* s = b; s != e; ++s) {
        const double q = q_of(mesh, *s);
        cur += q;
        star_q = std::min(star_q, q);
      }
      if (!(cur < (interior ? o.star_below : o.boundary_star_below) * n)) continue;
      for (const int* s = b; s != e; ++s) star_a = std::min(star_a, angle_of(mesh, *s));
      if (!interior)
        for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f)
          fan_q = std::min(fan_q, tri_q_of(mesh, *f));
      const double q_low = std::min(star_q, q_floor), a_low = std::min(star_a, angle_floor),
                   t_low = std::min(fan_q, tri_floor);
      // Strictly above a_low (a margin over acos's rounding): the guard in cosines.
      const double cos_low = std::cos(a_low * kPi / 180) - 1e-12;
      ++stats.nb_tried;
      double* P = mesh.point(v);
      const Vec3 start = vec3(P);
      const double lmin = shortest_star_edge(mesh, b, e, v);
      if (!(lmin > 0) || lmin == kInf) continue;
      // The guards and the objective at the current position of v; false if a guard fails.
      auto evaluate = [&](double& sum) {
        sum = 0;
        for (const int* s = b; s != e; ++s) {
          const double q = q_of(mesh, *s);
          if (q < q_low) return false;
          sum += q;
        }
        for (const int* s = b; s != e; ++s)
          if (!angles_above(mesh, *s, cos_low)) return false;
        if (!interior)
          for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f)
            if (tri_q_of(mesh, *f) < t_low) return false;
        return true;
      };
      // The nodal time-step change of moving v from `from` to where it is now.
      auto nodal_change = [&](const Vec3& from) {
        dt_change.clear();
        const Vec3 now = vec3(P);
        for (int c = 0; c < 3; ++c) P[c] = from[c];
        for (const int* s = b; s != e; ++s) dt_change.add(mesh, tet_of(mesh, *s), -1);
        for (int c = 0; c < 3; ++c) P[c] = now[c];
        for (const int* s = b; s != e; ++s) dt_change.add(mesh, tet_of(mesh, *s), +1);
        return dt_change.allows(o.dt_guard, dt_steps);
      };
      const double start_sum = cur;
      double alpha = o.step * lmin;
      bool moved = false;
      for (int step = 0; step < o.max_steps; ++step) {
        Vec3 g{0, 0, 0};
        for (const int* s = b; s != e; ++s) {
          const int* w = tet_of(mesh, *s);
          const double* p[4] = {mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]),
                                mesh.point(w[3])};
          int k = 0;
          while (w[k] != v) ++k;
          double gk[3];
          tet_q_gradient(p, k, gk);
          g = g + vec3(gk);
        }
        if (!interior) {
          // Within the entity's tangent space: the fan's plane (a curve: the chord to the
          // projection of a probe along the gradient).
          if (model.role_of(v).role == BoundaryRole::kSurface) {
            const Vec3 nrm = fan_normal(mesh, fans, v);
            g = g - dot(g, nrm) * nrm;
          } else {
            const double gn = norm(g);
            if (!(gn > 0)) break;
            double probe[3], q[3];
            for (int c = 0; c < 3; ++c) probe[c] = P[c] + 0.1 * lmin * g[c] / gn;
            if (!project_on_entity(model, v, probe, q)) break;
            const Vec3 t = sub(q, P);
            const double tn = norm(t);
            if (!(tn > 1e-9 * lmin)) break;
            g = (dot(g, t) / (tn * tn)) * t;
          }
        }
        const double gn = norm(g);
        if (!(gn > 0)) break;
        const Vec3 d = (1 / gn) * g;
        const Vec3 here = vec3(P);
        bool accepted = false;
        for (int halving = 0; halving <= o.max_halvings && !accepted; ++halving, alpha *= 0.5) {
          double wanted[3];
          for (int c = 0; c < 3; ++c) wanted[c] = here[c] + alpha * d[c];
          if (interior) {
            for (int c = 0; c < 3; ++c) P[c] = wanted[c];
            bool positive = true;
            for (const int* s = b; s != e && positive; ++s) {
              const int* w = tet_of(mesh, *s);
              positive = orient3d(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]),
                                  mesh.point(w[3])) > 0;
            }
            double sum;
            if (positive && evaluate(sum) && sum > cur) {
              accepted = true;
              cur = sum;
            }
            if (!accepted)
              for (int c = 0; c < 3; ++c) P[c] = here[c];
            continue;
          }
          for (int c = 0; c < 3; ++c) P[c] = here[c];
          const PlannedBoundaryMove plan =
              plan_boundary_move(mesh, model, star, fans, v, wanted, kInf);
          if (plan.status != BoundaryMoveStatus::kOk) continue;
          // The volume change is measured from the vertex's start of this pass (the budget is
          // charged once, for the whole move).
          if (o.volume_budget) {
            for (int c = 0; c < 3; ++c) P[c] = start[c];
            const bool in_budget = o.volume_budget->admits(mesh, star, v, plan.position, delta);
            for (int c = 0; c < 3; ++c) P[c] = here[c];
            if (!in_budget) continue;
          }
          apply_boundary_move(mesh, v, plan);
          double sum;
          if (evaluate(sum) && sum > cur) {
            accepted = true;
            cur = sum;
          } else {
            for (int c = 0; c < 3; ++c) P[c] = here[c];
          }
        }
        if (!accepted) break;
        alpha *= 4;  // the next step may be longer than the one accepted (halved once above)
        ++stats.nb_steps;
        moved = true;
      }
      if (moved && cur < start_sum + o.min_gain) moved = false;
      // The costly checks once, at the vertex's final position: the time-step guard (element
      // and nodal steps), the Hausdorff tolerance.
      if (moved && o.dt_guard.on) {
        const double now_dt = min_time_step(mesh, b, e);
        const Vec3 now = vec3(P);
        for (int c = 0; c < 3; ++c) P[c] = start[c];
        const double start_dt = min_time_step(mesh, b, e);
        for (int c = 0; c < 3; ++c) P[c] = now[c];
        moved = time_step_allows(o.dt_guard, start_dt, now_dt) && nodal_change(start);
      }
      if (moved && !interior && !fan_within_tolerance(mesh, model, fans, v, P, o.hausdorff))
        moved = false;
      if (!moved) {
        for (int c = 0; c < 3; ++c) P[c] = start[c];
        continue;
      }
      if (o.dt_guard.on) dt_change.apply(dt_steps);  // nodal_change(start) made it
      if (!interior && o.volume_budget) {
        const Vec3 now = vec3(P);
        for (int c = 0; c < 3; ++c) P[c] = start[c];
        o.volume_budget->admits(mesh, star, v, now.data(), delta);
        o.volume_budget->commit(delta);
        for (int c = 0; c < 3; ++c) P[c] = now[c];
      }
      stats.sum_after += cur - start_sum;
      ++stats.nb_moved;
      ++moved_this_pass;
    }
    if (moved_this_pass == 0) break;
  }
  return stats;
}

}  // namespace cvtmesh
