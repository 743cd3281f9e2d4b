// The bounding-box diagonal of a mesh's vertices (0 for an empty mesh): the length scale of
// the free boundary's tolerances.
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

double bounding_box_diagonal(const TetMesh& mesh);

}  // namespace cvtmesh
