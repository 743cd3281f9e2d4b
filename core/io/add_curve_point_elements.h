// The model's curves and points as elements (lines, points) where the mesh has none, from the
// vertices' classification: Gmsh's partitioner (gmsh::model::mesh::partition) puts every node
// on the lowest-dimensional partition entity whose elements use it, so a node of a curve or
// point without elements would end up on a surface or in a volume. Used on the copy a
// partitioned output is built from (core/io/write_mesh.cpp).
#pragma once

#include "core/mesh/mesh_data.h"

namespace cvtmesh {

// Adds to data.model().extra a point element (Gmsh type 15) on every model point that holds a
// vertex and has no point element, and, in 3D, a line (type 1) on every edge of the boundary
// triangles that lies on a curve without lines: both ends on the curve or on its end points
// (ModelEntity::boundary), at least one on the curve, or both on the end points of a curve without
// vertices of its own. Element tags are left empty (fresh ones are given when written). Returns the
// number of elements added.
long add_curve_point_elements(MeshData& data);

}  // namespace cvtmesh
