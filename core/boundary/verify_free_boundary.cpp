#include "core/boundary/verify_free_boundary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/boundary/boundary_move.h"
#include "core/boundary/volume_budget.h"
#include "core/quality/quality.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

std::string str(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

double boundary_triangle_q_min(const TetMesh& m) {
  double q = 1;
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* v = &m.tris[3 * static_cast<std::size_t>(f)];
    q = std::min(q, tri_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), 3, Measure::kQ));
  }
  return q;
}

FreeBoundaryReport verify_free_boundary(const TetMesh& before, const TetMesh& after,
                                        const BoundaryModel& model,
                                        const FreeBoundaryTolerances& tol) {
  FreeBoundaryReport r;
  r.diagonal = model.diagonal;
  const int nv = std::min(before.nb_vertices(), after.nb_vertices());
  for (int v = 0; v < nv; ++v) {
    if (before.vclass[v].dim == 3) continue;
    const double* p = after.point(v);
    const bool moved =
        p[0] != before.point(v)[0] || p[1] != before.point(v)[1] || p[2] != before.point(v)[2];
    if (!moved) continue;
    if (!model.movable(v))
      throw InvariantError("fixed boundary vertex " + std::to_string(v) + " moved");
    ++r.nb_moved;
    double q[3];
    if (!project_on_entity(model, v, p, q))
      throw InvariantError("boundary vertex " + std::to_string(v) +
                           " cannot be projected on its entity");
    const double d = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                               (p[2] - q[2]) * (p[2] - q[2]));
    r.max_off_entity = std::max(r.max_off_entity, d);
  }
  if (r.max_off_entity > tol.on_entity * model.diagonal)
    throw InvariantError("a boundary vertex left its entity (distance " + str(r.max_off_entity) +
                         " > " + str(tol.on_entity * model.diagonal) + ")");
  r.hausdorff = boundary_hausdorff(after, *model.geometry);
  if (tol.hausdorff > 0 && r.hausdorff.value() > tol.hausdorff)
    throw InvariantError("the boundary moved farther than the Hausdorff tolerance (" +
                         str(r.hausdorff.value()) + " > " + str(tol.hausdorff) + "; new to input " +
                         str(r.hausdorff.to_reference) + ", input to new " +
                         str(r.hausdorff.from_reference) + ")");
  const auto vb = region_volumes_of(before), va = region_volumes_of(after);
  for (std::size_t i = 0; i < vb.size() && i < va.size(); ++i) {
    const double rel = std::fabs(va[i].second - vb[i].second) / std::fabs(vb[i].second);
    r.max_volume_change = std::max(r.max_volume_change, rel);
  }
  if (r.max_volume_change > tol.volume)
    throw InvariantError("a region's volume changed by " + str(100 * r.max_volume_change) +
                         " % (bound " + str(100 * tol.volume) + " %)");
  r.tri_q_min_before = boundary_triangle_q_min(before);
  r.tri_q_min_after = boundary_triangle_q_min(after);
  return r;
}

}  // namespace cvtmesh
