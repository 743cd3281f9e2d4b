#include "core/boundary/pattern_move.h"

#include <cmath>

#include "core/boundary/boundary_move.h"

namespace cvtmesh {

std::vector<Vec3> move_directions(const TetMesh& mesh, const BoundaryModel& model,
                                  const BoundaryFans& fans, int w, double len) {
  std::vector<Vec3> d;
  const BoundaryRole role = model.role_of(w).role;
  if (role == BoundaryRole::kInterior) {
    for (int k = 0; k < 3; ++k)
      for (double s : {1.0, -1.0}) {
        Vec3 e{0, 0, 0};
        e[k] = s;
        d.push_back(e);
      }
    const double r = 1 / std::sqrt(3.0);
    for (double x : {r, -r})
      for (double y : {r, -r})
        for (double z : {r, -r}) d.push_back({x, y, z});
    return d;
  }
  const double* P = mesh.point(w);
  if (role == BoundaryRole::kSurface) {
    const Vec3 n = fan_normal(mesh, fans, w);
    if (!(norm(n) > 0)) return d;
    const Vec3 nn = (1 / norm(n)) * n;
    // Two unit vectors spanning the plane orthogonal to nn.
    const Vec3 helper = std::fabs(nn[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    Vec3 u = cross(nn, helper);
    u = (1 / norm(u)) * u;
    const Vec3 v = cross(nn, u);
    for (int k = 0; k < 6; ++k) {
      const double a = k * 3.14159265358979323846 / 3;
      d.push_back(std::cos(a) * u + std::sin(a) * v);
    }
    return d;
  }
  Vec3 axis;
  if (role == BoundaryRole::kCurve && curve_tangent(model, w, P, len, axis.data())) {
    d.push_back(axis);
    d.push_back(-1.0 * axis);
  }
  return d;
}

bool may_move(const TetMesh& mesh, const BoundaryModel& model, int w) {
  return model.role_of(w).role == BoundaryRole::kInterior ? mesh.vclass[w].dim == 3
                                                          : model.geometry && model.movable(w);
}

bool pattern_move(TetMesh& mesh, const BoundaryModel& model, const VertexTets& vt,
                  const BoundaryFans& fans, int w, const std::function<double()>& value_of,
                  const PatternMoveOptions& o) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const bool interior = model.role_of(w).role == BoundaryRole::kInterior;
  double* P = mesh.point(w);
  const Vec3 start = vec3(P);
  const double start_value = value_of();
  if (!(start_value > -kInf) || start_value >= o.stop_at) return false;
  const double len = shortest_star_edge(mesh, vt.begin_of(w), vt.end_of(w), w);
  if (!(len > 0) || len == kInf) return false;
  const std::vector<Vec3> dirs = move_directions(mesh, model, fans, w, len);
  double value = start_value, step = o.initial_step * len;
  int evaluations = 0;
  while (step >= o.final_step * len && evaluations < o.max_evaluations) {
    const Vec3 here = vec3(P);
    Vec3 best_pos = here;
    double best = value;
    auto try_directions = [&](const std::vector<Vec3>& ds) {
      for (const Vec3& d : ds) {
        if (++evaluations > o.max_evaluations) break;
        const Vec3 wanted = here + step * d;
        Vec3 pos = wanted;
        if (!interior) {
          for (int c = 0; c < 3; ++c) P[c] = here[c];
          // The Hausdorff check after the cheaper ones, as the boundary max-min does.
          const PlannedBoundaryMove plan =
              plan_boundary_move(mesh, model, vt, fans, w, wanted.data(), kInf);
          if (plan.status != BoundaryMoveStatus::kOk) continue;
          pos = {plan.position[0], plan.position[1], plan.position[2]};
        }
        for (int c = 0; c < 3; ++c) P[c] = pos[c];
        if (!interior && !fan_within_tolerance(mesh, model, fans, w, pos.data(), o.hausdorff))
          continue;
        const double x = value_of();
        if (x > best) {
          best = x;
          best_pos = pos;
        }
      }
      for (int c = 0; c < 3; ++c) P[c] = here[c];
    };
    try_directions(dirs);
    if (!(best > value) && interior && o.extra_directions && evaluations < o.max_evaluations)
      try_directions(o.extra_directions(o.final_step * len));
    for (int c = 0; c < 3; ++c) P[c] = best_pos[c];
    if (best > value) {
      value = best;
      if (value >= o.stop_at) break;
    } else {
      step *= 0.5;
    }
  }
  bool keep = value > start_value * (1 + 1e-9);
  if (keep && !interior && o.volume_budget) {
    const Vec3 now = vec3(P);
    for (int c = 0; c < 3; ++c) P[c] = start[c];
    std::vector<double> delta;
    keep = o.volume_budget->admits(mesh, vt, w, now.data(), delta);
    if (keep) o.volume_budget->commit(delta);
    for (int c = 0; c < 3; ++c) P[c] = now[c];
  }
  if (!keep)
    for (int c = 0; c < 3; ++c) P[c] = start[c];
  return keep;
}

}  // namespace cvtmesh
