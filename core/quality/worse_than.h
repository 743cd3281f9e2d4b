// The "never worse than the input" criterion of optimize(): a mesh is worse than a reference if
// its minimum quality or minimum angle is lower, its maximum angle higher (dihedral angles in 3D,
// planar angles in 2D), its average quality lower (issue 14: t15 and two thin CSG parts ended
// below their input's average), or it has inverted/flat elements the reference has not.
#pragma once
#include <string>

#include "core/quality/quality_stats.h"

namespace cvtmesh {

// "" if `after` is not worse than `before`, else what is worse ("Q_min 0.222 -> 0.024").
std::string worse_than(const QualityStats& after, const QualityStats& before);

}  // namespace cvtmesh
