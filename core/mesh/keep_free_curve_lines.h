// Lines of a planar mesh that are not an edge of any triangle — a curve that bounds no surface
// (Gmsh's free curves: the spline demo's), a curve bounding only quadrangles — are not
// constraints of the triangle mesh: they move from mesh.edges to mesh.model.extra (one block per
// curve, Gmsh type 1, tags kept), where they are written back unchanged and their vertices stay
// where they are (pin_vertices.h). Lines on the triangles' edges (boundaries, interfaces, curves
// embedded in a surface) stay constrained edges.
#pragma once
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// Returns the number of lines moved. The adjacency need not be built.
int keep_free_curve_lines(TriMesh2& mesh);

}  // namespace cvtmesh
