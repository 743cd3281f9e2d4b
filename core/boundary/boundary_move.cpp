#include "core/boundary/boundary_move.h"

#include <algorithm>
#include <cmath>

#include "core/boundary/boundary_hausdorff.h"
#include "core/boundary/surface_folds.h"
#include "core/boundary/triangle_set_distance.h"
#include "core/geometry/predicates.h"
#include "core/geometry/vec3.h"

namespace cvtmesh {

bool project_on_entity(const BoundaryModel& model, int v, const double* p, double* q) {
  const VertexRole r = model.role_of(v);
  if (r.role == BoundaryRole::kSurface) return model.geometry->closest_on_surface(r.entity, p, q);
  if (r.role == BoundaryRole::kCurve) return model.geometry->closest_on_curve(r.entity, p, q);
  return false;
}

bool curve_tangent(const BoundaryModel& model, int v, const double* p, double len, double* axis) {
  if (model.role_of(v).role != BoundaryRole::kCurve) return false;
  double best = 0;
  for (int k = 0; k < 3; ++k) {
    double probe[3] = {p[0], p[1], p[2]}, q[3];
    probe[k] += 0.1 * len;
    if (!project_on_entity(model, v, probe, q)) continue;
    const Vec3 t = sub(q, p);
    if (norm(t) > best) {
      best = norm(t);
      const Vec3 u = (1 / best) * t;
      std::copy(u.begin(), u.end(), axis);
    }
  }
  return best > 1e-9 * len;
}

PlannedBoundaryMove plan_boundary_move(const TetMesh& m, const BoundaryModel& model,
                                       const VertexTets& star, const BoundaryFans& fans, int v,
                                       const double* wanted, double hausdorff) {
  PlannedBoundaryMove plan;
  if (!model.movable(v)) return plan;
  double q[3];
  if (!project_on_entity(model, v, wanted, q)) {
    plan.status = BoundaryMoveStatus::kNoProjection;
    return plan;
  }
  return check_boundary_move(m, model, star, fans, v, q, hausdorff);
}

PlannedBoundaryMove check_boundary_move(const TetMesh& m, const BoundaryModel& model,
                                        const VertexTets& star, const BoundaryFans& fans, int v,
                                        const double* position, double hausdorff) {
  PlannedBoundaryMove plan;
  for (int d = 0; d < 3; ++d) plan.position[d] = position[d];
  for (int d = 0; d < 3; ++d)
    if (!std::isfinite(plan.position[d])) {
      plan.status = BoundaryMoveStatus::kNoProjection;
      return plan;
    }
  auto at = [&](int w) { return w == v ? static_cast<const double*>(plan.position) : m.point(w); };
  for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) {
    const int* w = &m.tets[4 * static_cast<std::size_t>(*t)];
    if (orient3d(at(w[0]), at(w[1]), at(w[2]), at(w[3])) <= 0) {
      plan.status = BoundaryMoveStatus::kInverted;
      return plan;
    }
  }
  if (move_folds_surface(m, fans, v, plan.position)) {
    plan.status = BoundaryMoveStatus::kFolds;
    return plan;
  }
  if (std::isfinite(hausdorff) &&
      !fan_within_tolerance(m, model, fans, v, plan.position, hausdorff)) {
    plan.status = BoundaryMoveStatus::kTooFar;
    return plan;
  }
  plan.status = BoundaryMoveStatus::kOk;
  return plan;
}

bool fan_within_tolerance(const TetMesh& m, const BoundaryModel& model, const BoundaryFans& fans,
                          int v, const double* position, double hausdorff) {
  // The new side: the sample points of every fan triangle (centroid, edge midpoints, the points
  // (2/3, 1/6, 1/6)), as the end-of-run check samples them.
  auto at = [&](int w) { return w == v ? position : m.point(w); };
  for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f) {
    const int* w = &m.tris[3 * static_cast<std::size_t>(*f)];
    double p[10][3];
    triangle_samples(at(w[0]), at(w[1]), at(w[2]), p);
    for (int i = 3; i < 10; ++i)
      if (!model.geometry->within_distance(p[i], hausdorff)) return false;
  }
  // The other side: the input position of every vertex of the fan stays within the tolerance of
  // that vertex's own (new) fan.
  for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f)
    for (int k = 0; k < 3; ++k) {
      const int u = m.tris[3 * static_cast<std::size_t>(*f) + k];
      if (!fan_covers_input(m, model, fans, u, v, position, hausdorff)) return false;
    }
  return true;
}

bool fan_covers_input(const TetMesh& m, const BoundaryModel& model, const BoundaryFans& fans, int u,
                      int v, const double* position, double hausdorff) {
  if (model.input_xyz.size() < 3 * static_cast<std::size_t>(u) + 3) return true;
  const double* p0 = &model.input_xyz[3 * static_cast<std::size_t>(u)];
  auto at = [&](int w) { return w == v ? position : m.point(w); };
  for (const int* f = fans.begin_of(u); f != fans.end_of(u); ++f) {
    const int* w = &m.tris[3 * static_cast<std::size_t>(*f)];
    if (point_triangle_distance(p0, at(w[0]), at(w[1]), at(w[2])) <= hausdorff) return true;
  }
  return fans.begin_of(u) == fans.end_of(u);
}

void apply_boundary_move(TetMesh& m, int v, const PlannedBoundaryMove& move) {
  double* p = m.point(v);
  for (int d = 0; d < 3; ++d) p[d] = move.position[d];
}

}  // namespace cvtmesh
