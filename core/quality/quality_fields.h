// The per-element quality fields written with --quality and shown as Gmsh views: Q, radius
// ratio, min dihedral (3D) / min angle (2D and a surface mesh in space, whose elements are its
// triangles), one value per live element in element order.
#pragma once
#include <vector>

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

std::vector<ElementField> quality_fields(const MeshData& data);

}  // namespace cvtmesh
