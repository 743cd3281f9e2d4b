#include "core/quality/element_shortfall.h"

#include <algorithm>

namespace cvtmesh {

double element_shortfall(double q, double min_angle, double max_angle, const QualityStats& ref) {
  return std::max(0.0, ref.q_min - q) + std::max(0.0, ref.min_angle - min_angle) / 180 +
         std::max(0.0, max_angle - ref.max_angle) / 180;
}

double tet_shortfall(const double* a, const double* b, const double* c, const double* d,
                     const QualityStats& ref) {
  return element_shortfall(tet_quality(a, b, c, d, Measure::kQ),
                           tet_quality(a, b, c, d, Measure::kMinAngle),
                           tet_quality(a, b, c, d, Measure::kMaxAngle), ref);
}

double tri_shortfall(const double* a, const double* b, const double* c, const QualityStats& ref) {
  return element_shortfall(tri_quality(a, b, c, 2, Measure::kQ),
                           tri_quality(a, b, c, 2, Measure::kMinAngle),
                           tri_quality(a, b, c, 2, Measure::kMaxAngle), ref);
}

}  // namespace cvtmesh
