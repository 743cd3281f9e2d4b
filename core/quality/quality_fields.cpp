#include "core/quality/quality_fields.h"

#include "core/quality/quality_stats.h"

namespace cvtmesh {

std::vector<ElementField> quality_fields(const MeshData& data) {
  std::vector<ElementField> f;
  if (data.dim == 3) {
    f.push_back({"Q (Du-Wang)", element_qualities(data.tet, Measure::kQ)});
    f.push_back({"Radius ratio 3r/R", element_qualities(data.tet, Measure::kRadiusRatio)});
    f.push_back({"Min dihedral angle", element_qualities(data.tet, Measure::kMinAngle)});
  } else {
    f.push_back({"Q (Du-Wang)", element_qualities(data.tri, Measure::kQ)});
    f.push_back({"Radius ratio 2r/R", element_qualities(data.tri, Measure::kRadiusRatio)});
    f.push_back({"Min angle", element_qualities(data.tri, Measure::kMinAngle)});
  }
  return f;
}

}  // namespace cvtmesh
