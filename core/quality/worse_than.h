// The "never worse than the input" criterion of optimize(): a mesh is worse than a reference if
// its minimum quality or minimum angle is lower, its maximum angle higher (dihedral angles in 3D,
// planar angles in 2D), its average quality lower (issue 14: t15 and two thin CSG parts ended
// below their input's average), or it has inverted/flat elements the reference has not.
#pragma once
#include <string>

#include "core/quality/quality_stats.h"

namespace cvtmesh {

// Differences a comparison of two results may ignore: a row within its tolerance of the
// reference's is not worse. The inverted count is always compared exactly.
struct RowTolerance {
  double q_min_relative = 0;  // Q_min: this fraction of the reference's Q_min
  double q_avg = 0;           // average quality
  double angle = 0;           // degrees, minimum and maximum angle
};

// "" if `after` is not worse than `before` (each row up to `tol`; by default exactly), else what
// is worse ("Q_min 0.222 -> 0.024").
std::string worse_than(const QualityStats& after, const QualityStats& before,
                       const RowTolerance& tol = {});

// Whether `after` is better than `before` on balance: past `tol` on both Q rows (Q_min and the
// average), no more inverted or flat elements, and with each row's difference counted in units
// of its tolerance (Q_min relative to before's, the average, the minimum and the maximum angle;
// a gain positive) a gain in sum. A result that gives up a little of an angle row for much on
// both Q rows (auto_refine). False unless every tolerance is positive.
bool better_on_balance(const QualityStats& after, const QualityStats& before,
                       const RowTolerance& tol);

}  // namespace cvtmesh
