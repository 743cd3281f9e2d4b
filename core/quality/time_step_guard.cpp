#include "core/quality/time_step_guard.h"

#include <algorithm>
#include <cmath>

#include "core/quality/quality.h"
#include "core/quality/quality_stats.h"

namespace cvtmesh {

bool time_step_allows(const TimeStepGuard& guard, double old_min, double new_min) {
  return !guard.on || new_min >= std::min(old_min, guard.floor);
}

double min_time_step(const TetMesh& mesh, const int* t, const int* end) {
  double m = std::numeric_limits<double>::infinity();
  for (; t != end; ++t) {
    const int* v = &mesh.tets[4 * static_cast<std::size_t>(*t)];
    m = std::min(m, tet_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]),
                                mesh.point(v[3]), Measure::kTimeStep));
  }
  return m;
}

double min_time_step(const TetMesh& mesh) {
  return min_quality(mesh, Measure::kTimeStep);
}

TimeStepGuard time_step_guard(const TetMesh& mesh, double factor) {
  TimeStepGuard g;
  g.on = true;
  g.floor = factor * min_time_step(mesh);
  g.vertex_floor = factor * min_vertex_time_step(mesh);
  return g;
}

void VertexStepChange::clear() {
  ids_.clear();
  dk_.clear();
  dm_.clear();
}

void VertexStepChange::add(const int* v, const double* const* p, double sign) {
  double k[4], m;
  tet_vertex_terms(p[0], p[1], p[2], p[3], k, &m);
  for (int i = 0; i < 4; ++i) {
    std::size_t at = 0;
    while (at < ids_.size() && ids_[at] != v[i]) ++at;
    if (at == ids_.size()) {
      ids_.push_back(v[i]);
      dk_.push_back(0);
      dm_.push_back(0);
    }
    dk_[at] += sign * k[i];
    dm_[at] += sign * m;
  }
}

void VertexStepChange::add(const TetMesh& mesh, const int* v, double sign) {
  const double* p[4] = {mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3])};
  add(v, p, sign);
}

bool VertexStepChange::allows(const TimeStepGuard& guard, const VertexTimeSteps& steps) const {
  if (!guard.on) return true;
  const double inf = std::numeric_limits<double>::infinity();
  double old_min = inf, new_min = inf;
  const int n = static_cast<int>(steps.kdiag.size());
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    const int v = ids_[i];
    const double k0 = v < n ? steps.kdiag[v] : 0, m0 = v < n ? steps.mass[v] : 0;
    const double k1 = k0 + dk_[i], m1 = m0 + dm_[i];
    if (k0 > 0 && m0 > 0) old_min = std::min(old_min, 2.0 / std::sqrt(k0 / m0));
    // A vertex left with no tet (rounding: a tiny positive remainder) has no mode.
    if (k1 > 1e-12 * std::fabs(k0) && m1 > 1e-12 * std::fabs(m0))
      new_min = std::min(new_min, 2.0 / std::sqrt(k1 / m1));
  }
  return new_min >= std::min(old_min, guard.vertex_floor);
}

void VertexStepChange::apply(VertexTimeSteps& steps) const {
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    const int v = ids_[i];
    if (v >= static_cast<int>(steps.kdiag.size())) {
      steps.kdiag.resize(v + 1, 0.0);
      steps.mass.resize(v + 1, 0.0);
    }
    steps.kdiag[v] += dk_[i];
    steps.mass[v] += dm_[i];
  }
}

}  // namespace cvtmesh
