#include "core/boundary/smooth_boundary_maxmin.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/boundary_move.h"
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

struct Elem {
  bool tet;
  int id;
};

// The functions of an element: a tet's Q and its six dihedral angles / scale; a triangle's Q.
int functions(const TetMesh& m, const Elem& e, double scale, double* f) {
  if (e.tet) {
    const int* v = &m.tets[4 * static_cast<std::size_t>(e.id)];
    const double *a = m.point(v[0]), *b = m.point(v[1]), *c = m.point(v[2]), *d = m.point(v[3]);
    f[0] = tet_quality(a, b, c, d, Measure::kQ);
    const auto ang = tet_dihedral_angles(a, b, c, d);
    for (int k = 0; k < 6; ++k) f[1 + k] = ang[k] * kDeg / scale;
    return 7;
  }
  const int* v = &m.tris[3 * static_cast<std::size_t>(e.id)];
  f[0] = tri_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), 3, Measure::kQ);
  return 1;
}

// The two measured values of an element (Q, min dihedral angle in degrees; a triangle: Q, +inf).
std::array<double, 2> measures(const TetMesh& m, const Elem& e) {
  if (e.tet) {
    const int* v = &m.tets[4 * static_cast<std::size_t>(e.id)];
    const double *a = m.point(v[0]), *b = m.point(v[1]), *c = m.point(v[2]), *d = m.point(v[3]);
    return {tet_quality(a, b, c, d, Measure::kQ), tet_quality(a, b, c, d, Measure::kMinAngle)};
  }
  const int* v = &m.tris[3 * static_cast<std::size_t>(e.id)];
  return {tri_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), 3, Measure::kQ), kInf};
}

}  // namespace

BoundaryMaxMinStats smooth_boundary_maxmin(TetMesh& mesh, const BoundaryModel& model,
                                           const BoundaryMaxMinOptions& o) {
  BoundaryMaxMinStats stats;
  if (!model.geometry) return stats;
  const VertexTets star = vertex_tets(mesh);
  const BoundaryFans fans = boundary_fans(mesh);
  const int nv = mesh.nb_vertices();
  const double scale = o.angle_scale > 0 ? o.angle_scale : 60;
  auto objective_of = [&](const std::array<double, 2>& q, bool tet) {
    return tet ? std::min(q[0], q[1] / scale) : q[0];
  };
  std::vector<Elem> elems;
  std::vector<std::array<double, 2>> low;
  std::vector<double> fv;
  std::vector<Vec3> fg;
  std::vector<std::pair<double, Vec3>> cand;
  for (int pass = 0; pass < o.passes; ++pass) {
    // The boundary vertices of poor elements, worst first.
    std::vector<std::pair<double, int>> todo;
    std::vector<double> worst(static_cast<std::size_t>(nv), kInf);
    const int nt = mesh.nb_tets();
    std::vector<std::array<double, 2>> tet_q(static_cast<std::size_t>(nt));
#pragma omp parallel for schedule(static, 1024) if (nt > 1024)
    for (int t = 0; t < nt; ++t)
      if (mesh.tets[4 * static_cast<std::size_t>(t)] >= 0) tet_q[t] = measures(mesh, {true, t});
    for (int t = 0; t < nt; ++t) {
      if (mesh.tets[4 * static_cast<std::size_t>(t)] < 0) continue;
      const auto q = tet_q[t];
      if (q[0] >= o.q_below && q[1] >= o.angle_below) continue;
      for (int k = 0; k < 4; ++k) {
        const int v = mesh.tets[4 * static_cast<std::size_t>(t) + k];
        worst[v] = std::min(worst[v], objective_of(q, true));
      }
    }
    for (int f = 0; f < mesh.nb_tris(); ++f) {
      const auto q = measures(mesh, {false, f});
      if (q[0] >= o.tri_below) continue;
      for (int k = 0; k < 3; ++k) {
        const int v = mesh.tris[3 * static_cast<std::size_t>(f) + k];
        worst[v] = std::min(worst[v], q[0]);
      }
    }
    for (int v = 0; v < nv; ++v)
      if (worst[v] < kInf && model.movable(v)) todo.push_back({worst[v], v});
    std::sort(todo.begin(), todo.end());
    long moved_this_pass = 0;
    for (const auto& [unused, v] : todo) {
      ++stats.nb_tried;
      elems.clear();
      for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) elems.push_back({true, *t});
      for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f) elems.push_back({false, *f});
      const int n = static_cast<int>(elems.size());
      double* P = mesh.point(v);
      const Vec3 start = vec3(P);
      double lmin = kInf;
      for (const int* t = star.begin_of(v); t != star.end_of(v); ++t)
        for (int j = 0; j < 4; ++j) {
          const int w = mesh.tets[4 * static_cast<std::size_t>(*t) + j];
          if (w != v) lmin = std::min(lmin, std::sqrt(dist2(P, mesh.point(w))));
        }
      if (!(lmin > 0) || lmin == kInf) continue;
      const double h = 1e-6 * lmin;
      // Current values, guards.
      low.resize(n);
      double cur = kInf, star_q = kInf, star_a = kInf, star_t = kInf;
      for (int i = 0; i < n; ++i) {
        const auto q = measures(mesh, elems[i]);
        cur = std::min(cur, objective_of(q, elems[i].tet));
        if (elems[i].tet) {
          star_q = std::min(star_q, q[0]);
          star_a = std::min(star_a, q[1]);
        } else {
          star_t = std::min(star_t, q[0]);
        }
      }
      for (int i = 0; i < n; ++i) {
        const auto q = measures(mesh, elems[i]);
        if (elems[i].tet)
          low[i] = {q[0] >= o.q_floor ? o.q_floor : star_q,
                    q[1] >= o.angle_floor ? o.angle_floor : star_a};
        else
          low[i] = {q[0] >= o.tri_floor ? o.tri_floor : star_t, -kInf};
      }
      auto evaluate = [&](double& obj) {
        obj = kInf;
        for (int i = 0; i < n; ++i) {
          const auto q = measures(mesh, elems[i]);
          if (q[0] < low[i][0] || q[1] < low[i][1]) return false;
          obj = std::min(obj, objective_of(q, elems[i].tet));
        }
        return true;
      };
      const double start_obj = cur;
      std::vector<double> delta;
      bool moved = false;
      for (int step = 0; step < o.max_steps; ++step) {
        // Values and finite-difference gradients of every function.
        fv.assign(7 * static_cast<std::size_t>(n), kInf);
        fg.assign(fv.size(), Vec3{0, 0, 0});
        std::vector<int> nf(n);
        for (int i = 0; i < n; ++i) nf[i] = functions(mesh, elems[i], scale, &fv[7 * i]);
        for (int c = 0; c < 3; ++c) {
          const double x0 = P[c];
          double fp[7], fm[7];
          for (int i = 0; i < n; ++i) {
            P[c] = x0 + h;
            functions(mesh, elems[i], scale, fp);
            P[c] = x0 - h;
            functions(mesh, elems[i], scale, fm);
            for (int j = 0; j < nf[i]; ++j) fg[7 * i + j][c] = (fp[j] - fm[j]) / (2 * h);
          }
          P[c] = x0;
        }
        // The entity's tangent space at v (the surface's plane, the curve's line): the ascent
        // direction is taken within it, so that the move is one along the entity.
        const VertexRole role = model.role_of(v);
        TangentSpace space;
        if (role.role == BoundaryRole::kSurface) {
          space.kind = TangentSpace::kPlane;
          space.axis = fan_normal(mesh, fans, v);
        } else {
          space.kind = TangentSpace::kLine;
          if (!curve_tangent(model, v, P, lmin, space.axis.data())) break;
        }
        cand.clear();
        double fmin = kInf;
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < nf[i]; ++j) {
            cand.push_back({fv[7 * i + j], fg[7 * i + j]});
            fmin = std::min(fmin, fv[7 * i + j]);
          }
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < nf[i]; ++j) {
            const double lo = j == 0 ? low[i][0] : low[i][1] / scale;
            if (lo > -kInf) cand.push_back({fv[7 * i + j] - lo + fmin, fg[7 * i + j]});
          }
        // The common ascent direction within the entity's tangent space.
        const AscentStep ascent = maxmin_ascent_step(cand, fmin, 0.2 * lmin, space);
        if (!ascent.ok) break;
        const Vec3& d = ascent.direction;
        double alpha = ascent.alpha;
        bool accepted = false;
        const Vec3 here = vec3(P);
        for (int halving = 0; halving <= o.max_halvings && !accepted; ++halving) {
          double wanted[3];
          for (int c = 0; c < 3; ++c) wanted[c] = here[c] + alpha * d[c];
          for (int c = 0; c < 3; ++c) P[c] = here[c];
          // The Hausdorff check last: it is the costly one.
          const PlannedBoundaryMove plan = plan_boundary_move(
              mesh, model, star, fans, v, wanted, std::numeric_limits<double>::infinity());
          // The volume change is measured from the vertex's start of this pass (the budget is
          // charged once, for the whole move).
          bool in_budget = true;
          if (plan.status == BoundaryMoveStatus::kOk && o.volume_budget) {
            for (int c = 0; c < 3; ++c) P[c] = start[c];
            in_budget = o.volume_budget->admits(mesh, star, v, plan.position, delta);
            for (int c = 0; c < 3; ++c) P[c] = here[c];
          }
          if (plan.status == BoundaryMoveStatus::kOk && in_budget) {
            apply_boundary_move(mesh, v, plan);
            double obj;
            if (evaluate(obj) && obj > cur &&
                fan_within_tolerance(mesh, model, fans, v, plan.position, o.hausdorff)) {
              accepted = true;
              cur = obj;
              break;
            }
          }
          alpha *= 0.5;
        }
        if (!accepted) {
          for (int c = 0; c < 3; ++c) P[c] = here[c];
          break;
        }
        ++stats.nb_steps;
        moved = true;
      }
      if (moved && cur < start_obj + o.min_gain) moved = false;
      if (moved && o.volume_budget) {
        const Vec3 now = vec3(P);
        for (int c = 0; c < 3; ++c) P[c] = start[c];
        o.volume_budget->admits(mesh, star, v, now.data(), delta);
        o.volume_budget->commit(delta);
        for (int c = 0; c < 3; ++c) P[c] = now[c];
      }
      if (moved) {
        ++stats.nb_moved;
        ++moved_this_pass;
      } else {
        for (int c = 0; c < 3; ++c) P[c] = start[c];
      }
    }
    if (moved_this_pass == 0) break;
  }
  return stats;
}

}  // namespace cvtmesh
