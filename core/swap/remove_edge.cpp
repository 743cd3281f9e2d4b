#include <utility>

#include "core/swap/remove_edge.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/geometry/predicates.h"
#include "core/swap/apply_swap.h"
#include "core/swap/edge_ring.h"
#include "core/swap/polygon_triangulations.h"

namespace cvtmesh {

SwapPlan plan_remove_edge(const TetMesh& mesh, const ConstrainedFaces& constrained, int t, int e,
                          Measure measure, int max_ring) {
  if (max_ring < 3 || max_ring > 7)
    throw std::invalid_argument("remove_edge: max_ring must be 3..7, not " +
                                std::to_string(max_ring));
  return plan_remove_edge(mesh, constrained, edge_ring(mesh, t, e, max_ring), measure);
}

SwapPlan plan_remove_edge(const TetMesh& mesh, const ConstrainedFaces& constrained,
                          const EdgeRing& r, Measure measure, double floor) {
  SwapPlan plan;
  plan.old_tets = r.tets;
  if (r.tets.empty()) throw std::invalid_argument("remove_edge: empty edge ring");
  plan.region = mesh.tet_region[r.tets[0]];
  if (!r.closed) {
    plan.status = r.on_boundary ? SwapStatus::kBoundary : SwapStatus::kRingSize;
    return plan;
  }
  const int n = static_cast<int>(r.ring.size());
  if (n < 3 || n > 7) {
    plan.status = SwapStatus::kRingSize;
    return plan;
  }
  for (int id : r.tets)
    if (mesh.tet_region[id] != plan.region) {
      plan.status = SwapStatus::kMixedRegions;
      return plan;
    }
  for (int v : r.ring)
    if (constrained.count(face_key(r.p, r.q, v))) {
      plan.status = SwapStatus::kConstrainedFace;
      return plan;
    }

  // Quality of the two tets standing on each triangle of the ring polygon, evaluated lazily;
  // -inf if either is not positively oriented. Orientation is decided exactly, quality only
  // ranks. Branch and bound: a triangulation is abandoned as soon as one of its triangles is no
  // better than the best triangulation found so far, or than the floor (the result is the exact
  // max-min). A triangle whose first tet is already no better than the bound keeps that tet's
  // quality only: every triangulation holding it is abandoned (the bound only rises).
  constexpr double kInvalid = -std::numeric_limits<double>::infinity();
  const double kUnknown = std::numeric_limits<double>::quiet_NaN();
  const PolygonTriangulations& table = polygon_triangulations(n);
  const double* P = mesh.point(r.p);
  const double* Q = mesh.point(r.q);
  double tri_q[35];
  std::fill(tri_q, tri_q + table.triangles.size(), kUnknown);
  int best = -1;
  double best_q = std::max(kInvalid, floor);
  auto triangle_quality = [&](int i) {
    if (tri_q[i] == tri_q[i]) return tri_q[i];
    const auto& tr = table.triangles[i];
    const double* A = mesh.point(r.ring[tr[0]]);
    const double* B = mesh.point(r.ring[tr[1]]);
    const double* C = mesh.point(r.ring[tr[2]]);
    if (orient3d(A, B, C, Q) <= 0 || orient3d(A, C, B, P) <= 0) {
      tri_q[i] = kInvalid;
    } else {
      tri_q[i] = tet_quality(A, B, C, Q, measure);
      if (tri_q[i] > best_q) tri_q[i] = std::min(tri_q[i], tet_quality(A, C, B, P, measure));
    }
    return tri_q[i];
  };
  for (std::size_t k = 0; k < table.triangulations.size(); ++k) {
    double m = std::numeric_limits<double>::infinity();
    for (int i : table.triangulations[k]) {
      m = std::min(m, triangle_quality(i));
      if (m <= best_q) break;
    }
    if (m > best_q) {
      best_q = m;
      best = static_cast<int>(k);
    }
  }
  if (best < 0) {
    plan.status = floor > kInvalid ? SwapStatus::kRejected : SwapStatus::kNotConvex;
    return plan;
  }
  for (int i : table.triangulations[best]) {
    const auto& tr = table.triangles[i];
    const int a = r.ring[tr[0]], b = r.ring[tr[1]], c = r.ring[tr[2]];
    plan.new_tets.push_back({a, b, c, r.q});
    plan.new_tets.push_back({a, c, b, r.p});
  }
  plan.quality_known = true;
  plan.measure = measure;
  plan.new_min = best_q;
  plan.old_min = std::numeric_limits<double>::infinity();
  for (int id : r.tets) {
    const int* v = &mesh.tets[4 * static_cast<std::size_t>(id)];
    plan.old_min = std::min(plan.old_min, tet_quality(mesh.point(v[0]), mesh.point(v[1]),
                                                      mesh.point(v[2]), mesh.point(v[3]), measure));
  }
  return plan;
}

SwapPlan remove_edge(TetMesh& mesh, int t, int e, const SwapCriterion* criterion) {
  const Measure m = criterion ? criterion->measure : Measure::kQ;
  SwapPlan plan = plan_remove_edge(mesh, constrained_faces(mesh), t, e, m);
  return apply_if_accepted(mesh, std::move(plan), criterion);
}

}  // namespace cvtmesh
