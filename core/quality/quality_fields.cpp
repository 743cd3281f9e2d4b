#include "core/quality/quality_fields.h"

#include "core/mesh/check_surface_mesh.h"
#include "core/quality/quality_stats.h"

namespace cvtmesh {

std::vector<ElementField> quality_fields(const MeshData& data) {
  std::vector<ElementField> f;
  // A surface mesh in space (a TetMesh without tets): its elements are its triangles, measured as
  // triangles (element_qualities), named as the 2D fields.
  if (data.dim == 3 && !is_surface_mesh(data.tet)) {
    f.push_back({"Q (Du-Wang)", element_qualities(data.tet, Measure::kQ)});
    f.push_back({"Radius ratio 3r/R", element_qualities(data.tet, Measure::kRadiusRatio)});
    f.push_back({"Min dihedral angle", element_qualities(data.tet, Measure::kMinAngle)});
  } else if (data.dim == 3) {
    f.push_back({"Q (Du-Wang)", element_qualities(data.tet, Measure::kQ)});
    f.push_back({"Radius ratio 2r/R", element_qualities(data.tet, Measure::kRadiusRatio)});
    f.push_back({"Min angle", element_qualities(data.tet, Measure::kMinAngle)});
  } else {
    f.push_back({"Q (Du-Wang)", element_qualities(data.tri, Measure::kQ)});
    f.push_back({"Radius ratio 2r/R", element_qualities(data.tri, Measure::kRadiusRatio)});
    f.push_back({"Min angle", element_qualities(data.tri, Measure::kMinAngle)});
  }
  return f;
}

}  // namespace cvtmesh
