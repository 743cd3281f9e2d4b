#include "core/quality/worse_than.h"

#include <cstdio>

namespace cvtmesh {

std::string worse_than(const QualityStats& a, const QualityStats& b, const RowTolerance& tol) {
  char buf[160];
  const char* angle = a.dim == 3 ? "dihedral" : "angle";
  if (a.nb_inverted > b.nb_inverted) {
    std::snprintf(buf, sizeof buf, "%ld inverted or flat elements", a.nb_inverted);
    return buf;
  }
  if (a.q_min < b.q_min - tol.q_min_relative * b.q_min) {
    std::snprintf(buf, sizeof buf, "Q_min %.4f -> %.4f", b.q_min, a.q_min);
    return buf;
  }
  if (a.min_angle < b.min_angle - tol.angle) {
    std::snprintf(buf, sizeof buf, "min %s %.2f -> %.2f degrees", angle, b.min_angle, a.min_angle);
    return buf;
  }
  if (a.max_angle > b.max_angle + tol.angle) {
    std::snprintf(buf, sizeof buf, "max %s %.2f -> %.2f degrees", angle, b.max_angle, a.max_angle);
    return buf;
  }
  if (a.q_avg < b.q_avg - tol.q_avg) {
    std::snprintf(buf, sizeof buf, "average Q %.4f -> %.4f", b.q_avg, a.q_avg);
    return buf;
  }
  return "";
}

bool better_on_balance(const QualityStats& a, const QualityStats& b, const RowTolerance& tol) {
  if (!(tol.q_min_relative > 0 && tol.q_avg > 0 && tol.angle > 0) || !(b.q_min > 0)) return false;
  if (a.nb_inverted > b.nb_inverted) return false;
  const double q_min = (a.q_min - b.q_min) / (tol.q_min_relative * b.q_min);
  const double q_avg = (a.q_avg - b.q_avg) / tol.q_avg;
  const double min_angle = (a.min_angle - b.min_angle) / tol.angle;
  const double max_angle = (b.max_angle - a.max_angle) / tol.angle;
  return q_min > 1 && q_avg > 1 && q_min + q_avg + min_angle + max_angle > 0;
}

}  // namespace cvtmesh
