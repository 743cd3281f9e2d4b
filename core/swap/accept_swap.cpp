#include "core/swap/accept_swap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cvtmesh {

void check_swap_measure(Measure m) {
  if (m == Measure::kMaxAngle)
    throw std::invalid_argument("swap criterion: measure '" + measure_name(m) +
                                "' is not larger-is-better; use q, radius-ratio, min-angle or icn");
}

double min_quality(const TetMesh& mesh, const std::vector<std::array<int, 4>>& tets, Measure m) {
  double q = std::numeric_limits<double>::infinity();
  for (const auto& t : tets)
    q = std::min(
        q, tet_quality(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(t[3]), m));
  return q;
}

double min_quality(const TetMesh& mesh, const std::vector<int>& tet_ids, Measure m) {
  double q = std::numeric_limits<double>::infinity();
  for (int t : tet_ids) {
    const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
    q = std::min(
        q, tet_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]), m));
  }
  return q;
}

double accept_floor(double old_min, const SwapCriterion& criterion) {
  return old_min + criterion.min_gain * std::fabs(old_min);
}

bool accept_swap(double old_min, double new_min, const SwapCriterion& criterion) {
  return new_min > accept_floor(old_min, criterion);
}

bool accept_swap(const TetMesh& mesh, const SwapPlan& plan, const SwapCriterion& criterion) {
  check_swap_measure(criterion.measure);
  if (plan.status != SwapStatus::kOk) return false;
  if (plan.quality_known && plan.measure == criterion.measure)
    return accept_swap(plan.old_min, plan.new_min, criterion);
  return accept_swap(min_quality(mesh, plan.old_tets, criterion.measure),
                     min_quality(mesh, plan.new_tets, criterion.measure), criterion);
}

}  // namespace cvtmesh
