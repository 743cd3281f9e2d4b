// optimize() for a surface mesh in space (a TetMesh without tets whose `tris` are the surface:
// core/mesh/check_surface_mesh.h): the triangles optimized on the reference geometry
// (core/boundary/optimize_surface_mesh.h), the file's lines kept as edges, and the result checked
// (valid, no new fold, within the Hausdorff bound) and never worse than the input on Q_min, the
// minimum and the maximum angle (the input is kept otherwise, with a note). Only the default
// method (cvdt+swap+smooth) without fix_boundary moves vertices; the others flip coplanar edges.
#pragma once
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"
#include "core/pipeline/optimize.h"

namespace cvtmesh {

// `model` built for `mesh` with its pinned vertices fixed (pin_vertices.h); `operators`: the
// Hausdorff bound the moves and flips work to, `bound`: the one the result is checked against
// (absolute). Fills r (before, after, notes, the free boundary's figures).
void optimize_surface3(TetMesh& mesh, const OptimizeOptions& options, const BoundaryModel& model,
                       double operators, double bound, OptimizeResult& r);

}  // namespace cvtmesh
