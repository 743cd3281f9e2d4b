// A reference geometry that projects by one geometry (a CAD model's, through Gmsh) and measures
// distances on the input boundary triangulation first (a CGAL AABB tree, core/boundary/
// triangle_set_distance.h). The Hausdorff checks of every move ask for the distance from a point
// to the whole reference boundary; through the CAD alone that was a getClosestPoint on every
// surface of the model for every sample (serial Gmsh calls: 74 s instead of 1.2 s on Gmsh's t2).
//
// By the triangle inequality d(p, CAD) <= d(p, input) + reference_deviation (the input's own
// distance to the CAD) =: u, and d(p, CAD) <= d(p, S) for the CAD surface S of the input triangle
// nearest p. The distance returned is u where u <= exact_above (no CAD query), else min(u, d(p, S))
// (one query): an upper bound of d(p, CAD) either way, so every Hausdorff check and the
// end-of-run measure stay conservative, and a check against a tolerance >= exact_above decides as
// the CAD would on the nearest surface. On planar models (deviation 0) no distance reaches the
// CAD; on a coarse mesh of a curved surface (deviation near the tolerance) the samples near it
// cost one query each instead of one per surface.
#pragma once
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// `model` as built for `input` (its geometry projects, its surface ids are input.tri_surface's
// tags, its reference_deviation bounds the input boundary's distance to it); returns the same
// model with the geometry above. Projections, samples, kind and thread_safe are the wrapped
// geometry's. A model without geometry is returned as it is.
BoundaryModel measure_on_input_boundary(BoundaryModel model, const TetMesh& input,
                                        double exact_above);

}  // namespace cvtmesh
