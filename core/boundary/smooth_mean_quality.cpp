#include "core/boundary/smooth_mean_quality.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/boundary_move.h"
#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/geometry/vec3.h"
#include "core/mesh/colour_vertices.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/quality.h"

namespace cvtmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
// A colour of fewer interior vertices moves on one thread (a fork/join would cost more).
constexpr int kParallelColour = 256;

const int* tet_of(const TetMesh& m, int t) {
  return &m.tets[4 * static_cast<std::size_t>(t)];
}

double q_of(const TetMesh& m, int t) {
  const int* v = tet_of(m, t);
  return tet_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]), Measure::kQ);
}

// The minimum and maximum dihedral angle of tet t (degrees), from one evaluation of its angles
// (tet_table_qualities: bitwise tet_quality's kMinAngle and kMaxAngle).
std::pair<double, double> angles_of(const TetMesh& m, int t) {
  const int* v = tet_of(m, t);
  const std::array<double, 4> a =
      tet_table_qualities(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
  return {a[2], a[3]};
}

// Whether every dihedral angle of tet t is above the angle whose cosine is cos_low and below the
// one whose cosine is cos_high (the cosines compared: no acos), with the faces' normals as
// tet_dihedral_angles takes them.
bool angles_within(const TetMesh& m, int t, double cos_low, double cos_high) {
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
      if (-dot(n[k], n[j]) > cos_low * l[k] * l[j] || -dot(n[k], n[j]) < cos_high * l[k] * l[j])
        return false;
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

namespace {

// One vertex's ascent (see the header): the state shared by the moves of a pass (read only while
// a colour of interior vertices moves in parallel) and each thread's scratch.
struct MeanMover {
  TetMesh& mesh;
  const BoundaryModel& model;
  const MeanQualityOptions& o;
  const VertexTets& star;
  const BoundaryFans& fans;
  const VertexTimeSteps& dt_steps;
  double q_floor, angle_floor, tri_floor, angle_ceiling;
};

struct MeanScratch {
  VertexStepChange dt_change;  // of the last move tried (interior moves: judged by the caller)
  std::vector<double> delta;
};

// The outcome of moving one vertex.
struct MeanMove {
  bool tried = false, moved = false;
  long steps = 0;
  double gain = 0;  // the star's sum of Q, after minus before
  Vec3 start{0, 0, 0};
};

// Tries vertex v: the gradient ascent, then the guards at its final position. On success v is at
// its new position and, with the time-step guard on, s.dt_change holds the nodal change (already
// judged against m.dt_steps and, for a boundary vertex, applied by the caller; an interior vertex's
// change is judged again by the caller). A boundary move is charged to the volume budget here.
// Reads and writes only v's point; reads v's star, fan and (for a boundary vertex) the budget.
MeanMove try_mean_move(const MeanMover& m, int v, MeanScratch& s) {
  TetMesh& mesh = m.mesh;
  const BoundaryModel& model = m.model;
  const MeanQualityOptions& o = m.o;
  const VertexTets& star = m.star;
  const BoundaryFans& fans = m.fans;
  MeanMove r;
  const bool interior = mesh.vclass[v].dim == 3;
  const int *b = star.begin_of(v), *e = star.end_of(v);
  const int n = static_cast<int>(e - b);
  if (n == 0) return r;
  double cur = 0, star_q = kInf, star_a = kInf, fan_q = kInf;
  for (const int* t = b; t != e; ++t) {
    const double q = q_of(mesh, *t);
    cur += q;
    star_q = std::min(star_q, q);
  }
  if (!(cur < (interior ? o.star_below : o.boundary_star_below) * n)) return r;
  double star_max = 0;
  for (const int* t = b; t != e; ++t) {
    const auto [lo, hi] = angles_of(mesh, *t);
    star_a = std::min(star_a, lo);
    star_max = std::max(star_max, hi);
  }
  if (!interior)
    for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f)
      fan_q = std::min(fan_q, tri_q_of(mesh, *f));
  const double q_low = std::min(star_q, m.q_floor), a_low = std::min(star_a, m.angle_floor),
               t_low = std::min(fan_q, m.tri_floor);
  // Strictly above a_low (a margin over acos's rounding): the guard in cosines.
  const double cos_low = std::cos(a_low * kPi / 180) - 1e-12;
  // Not above max(the star's maximum dihedral angle before, the ceiling), likewise.
  const double a_high = std::max(star_max, m.angle_ceiling);
  const double cos_high = a_high >= 180 ? -2.0 : std::cos(a_high * kPi / 180) - 1e-12;
  r.tried = true;
  double* P = mesh.point(v);
  const Vec3 start = vec3(P);
  r.start = start;
  const double lmin = shortest_star_edge(mesh, b, e, v);
  if (!(lmin > 0) || lmin == kInf) return r;
  // The guards and the objective at the current position of v; false if a guard fails.
  auto evaluate = [&](double& sum) {
    sum = 0;
    for (const int* t = b; t != e; ++t) {
      const double q = q_of(mesh, *t);
      if (q < q_low) return false;
      sum += q;
    }
    for (const int* t = b; t != e; ++t)
      if (!angles_within(mesh, *t, cos_low, cos_high)) return false;
    if (!interior)
      for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f)
        if (tri_q_of(mesh, *f) < t_low) return false;
    return true;
  };
  // The nodal time-step change of moving v from `from` to where it is now.
  auto nodal_change = [&](const Vec3& from) {
    s.dt_change.clear();
    const Vec3 now = vec3(P);
    for (int c = 0; c < 3; ++c) P[c] = from[c];
    for (const int* t = b; t != e; ++t) s.dt_change.add(mesh, tet_of(mesh, *t), -1);
    for (int c = 0; c < 3; ++c) P[c] = now[c];
    for (const int* t = b; t != e; ++t) s.dt_change.add(mesh, tet_of(mesh, *t), +1);
    return s.dt_change.allows(o.dt_guard, m.dt_steps);
  };
  const double start_sum = cur;
  double alpha = o.step * lmin;
  bool moved = false;
  for (int step = 0; step < o.max_steps; ++step) {
    Vec3 g{0, 0, 0};
    for (const int* t = b; t != e; ++t) {
      const int* w = tet_of(mesh, *t);
      const double* p[4] = {mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3])};
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
        for (const int* t = b; t != e && positive; ++t) {
          const int* w = tet_of(mesh, *t);
          positive =
              orient3d(mesh.point(w[0]), mesh.point(w[1]), mesh.point(w[2]), mesh.point(w[3])) > 0;
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
      const PlannedBoundaryMove plan = plan_boundary_move(mesh, model, star, fans, v, wanted, kInf);
      if (plan.status != BoundaryMoveStatus::kOk) continue;
      // The volume change is measured from the vertex's start of this pass (the budget is
      // charged once, for the whole move).
      if (o.volume_budget) {
        for (int c = 0; c < 3; ++c) P[c] = start[c];
        const bool in_budget = o.volume_budget->admits(mesh, star, v, plan.position, s.delta);
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
    ++r.steps;
    moved = true;
  }
  if (moved && cur < start_sum + o.min_gain) moved = false;
  // The costly checks once, at the vertex's final position: the time-step guard (element and
  // nodal steps), the Hausdorff tolerance.
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
    return r;
  }
  if (!interior && o.volume_budget) {
    const Vec3 now = vec3(P);
    for (int c = 0; c < 3; ++c) P[c] = start[c];
    o.volume_budget->admits(mesh, star, v, now.data(), s.delta);
    o.volume_budget->commit(s.delta);
    for (int c = 0; c < 3; ++c) P[c] = now[c];
  }
  r.moved = true;
  r.gain = cur - start_sum;
  return r;
}

}  // namespace

MeanQualityStats smooth_mean_quality(TetMesh& mesh, const BoundaryModel& model,
                                     const MeanQualityOptions& o) {
  if (o.passes < 0 || o.max_steps < 0 || o.max_halvings < 0 || !(o.step > 0))
    throw std::invalid_argument(
        "smooth_mean_quality: passes, max_steps, max_halvings must be >= 0 and step > 0");
  MeanQualityStats stats;
  const int nv = mesh.nb_vertices(), nt = mesh.nb_tets();
  const bool boundary = o.boundary && model.geometry;
  // The floors, raised to the mesh's minima at the start (as smooth_maxmin3's), and the ceiling,
  // lowered to its maximum dihedral angle: so no move takes a value from above the mesh's minimum
  // to below it (from below its maximum to above it), and the minima never fall (nor the maximum
  // dihedral angle rise).
  double q_floor = o.q_floor, angle_floor = o.angle_floor, tri_floor = o.tri_floor,
         angle_ceiling = o.angle_ceiling;
  {
    double sum = 0, q_min = kInf, a_min = kInf, t_min = kInf, a_max = 0;
    long live = 0;
#pragma omp parallel for schedule(static, 4096) reduction(+ : sum, live) reduction(min : q_min, a_min) reduction(max : a_max) if (nt > 4096)
    for (int t = 0; t < nt; ++t)
      if (tet_of(mesh, t)[0] >= 0) {
        const double q = q_of(mesh, t);
        ++live;
        sum += q;
        q_min = std::min(q_min, q);
        const auto [lo, hi] = angles_of(mesh, t);
        a_min = std::min(a_min, lo);
        a_max = std::max(a_max, hi);
      }
    if (boundary)
      for (int f = 0; f < mesh.nb_tris(); ++f) t_min = std::min(t_min, tri_q_of(mesh, f));
    stats.sum_before = stats.sum_after = sum;
    stats.nb_tets = live;
    q_floor = std::max(q_floor, q_min);
    angle_floor = std::max(angle_floor, a_min);
    if (t_min < kInf) tri_floor = std::max(tri_floor, t_min);
    if (live > 0 && angle_ceiling < 180) angle_ceiling = std::min(angle_ceiling, a_max);
  }
  const VertexTets star = vertex_tets(mesh);
  const BoundaryFans fans = boundary_fans(mesh);
  VertexTimeSteps dt_steps;
  if (o.dt_guard.on) dt_steps = vertex_time_steps(mesh);
  const MeanMover mover{mesh,     model,   o,           star,      fans,
                        dt_steps, q_floor, angle_floor, tri_floor, angle_ceiling};
  // The interior vertices move colour by colour (no two of a colour share a tet: each reads its
  // star, of other colours, and writes its own point), in parallel; the surface and curve
  // vertices then one by one in vertex order (they share the volume budget). The result does not
  // depend on the number of threads.
  std::vector<int> inner, outer;
  for (int v = 0; v < nv; ++v) {
    if (star.nb_tets_of(v) == 0) continue;
    if (mesh.vclass[v].dim == 3) {
      if (o.interior) inner.push_back(v);
    } else if (boundary && model.movable(v)) {
      outer.push_back(v);
    }
  }
  const VertexColouring colours = colour_vertices(nv, inner, [&](int v, std::vector<int>& out) {
    for (const int* t = star.begin_of(v); t != star.end_of(v); ++t)
      out.insert(out.end(), tet_of(mesh, *t), tet_of(mesh, *t) + 4);
  });
  std::vector<MeanMove> moves;
  std::vector<VertexStepChange> changes;
  MeanScratch scratch;
  for (int pass = 0; pass < o.passes; ++pass) {
    long moved_this_pass = 0;
    for (int c = 0; c < colours.nb_colours(); ++c) {
      const int size = colours.size_of(c);
      const int* vs = colours.begin_of(c);
      moves.assign(static_cast<std::size_t>(size), MeanMove{});
      if (o.dt_guard.on) changes.resize(static_cast<std::size_t>(size));
#pragma omp parallel if (size > kParallelColour)
      {
        MeanScratch mine;
#pragma omp for schedule(dynamic, 256)
        for (int i = 0; i < size; ++i) {
          moves[i] = try_mean_move(mover, vs[i], mine);
          if (moves[i].moved && o.dt_guard.on) changes[i] = mine.dt_change;
        }
      }
      // In vertex order: the nodal sums with the colour's earlier moves applied (each move was
      // judged on the sums before the colour); a move that now fails is undone (its star's tets
      // hold no other vertex of the colour, so its other guards still hold).
      for (int i = 0; i < size; ++i) {
        const MeanMove& mv = moves[i];
        stats.nb_tried += mv.tried;
        if (!mv.moved) continue;
        if (o.dt_guard.on) {
          if (!changes[i].allows(o.dt_guard, dt_steps)) {
            for (int k = 0; k < 3; ++k) mesh.point(vs[i])[k] = mv.start[k];
            continue;
          }
          changes[i].apply(dt_steps);
        }
        stats.nb_steps += mv.steps;
        stats.sum_after += mv.gain;
        ++stats.nb_moved;
        ++moved_this_pass;
      }
    }
    for (int v : outer) {
      const MeanMove mv = try_mean_move(mover, v, scratch);
      stats.nb_tried += mv.tried;
      if (!mv.moved) continue;
      if (o.dt_guard.on) scratch.dt_change.apply(dt_steps);
      stats.nb_steps += mv.steps;
      stats.sum_after += mv.gain;
      ++stats.nb_moved;
      ++moved_this_pass;
    }
    if (moved_this_pass == 0) break;
  }
  return stats;
}

}  // namespace cvtmesh
