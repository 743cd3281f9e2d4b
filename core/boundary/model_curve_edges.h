// The curves' edges of a mesh classified on a Gmsh model (issue 13). Without them
// (BoundaryModel::curve_edges_known false: the CAD geometry) the surface flips and cap removals
// take every boundary edge whose two ends are off the surfaces for a curve's edge, and refuse it;
// on a model whose faces are narrow between curves many are chords across a face (t20, the sliced
// STEP model: 243 of the 777 such boundary edges after the default pipeline are no line element).
// A boundary triangle's edge (a, b), both ends of class dim <= 1, is taken as a curve's edge when
// one curve of the model holds both ends: a vertex on the curve (class dim 1, that tag) or a
// corner bounding it (class dim 0, a point of the curve's boundary in model.entities); also when
// an end is unclassified (entity 0) or a point that bounds no curve of the model. So no curve's
// edge is ever missed: a pair on one curve that is a chord stays refused, as before. Pinned
// vertices (pin_vertices) are read through their encoded class.
#pragma once
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// Fills model.curve_edges (sorted, smaller id first) and sets model.curve_edges_known from the
// mesh's boundary triangles (mesh.tris, #F by 3, 0-based), its classes (mesh.vclass) and its
// model's entities (mesh.model.entities). Returns false and leaves the model unchanged when the
// mesh has no model curve (no entity of dim 1): then nothing is known.
bool set_model_curve_edges(const TetMesh& mesh, BoundaryModel& model);

}  // namespace cvtmesh
