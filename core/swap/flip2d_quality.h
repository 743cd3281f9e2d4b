// Quality acceptance test of the 2D edge flip (flip2d.h).
#pragma once
#include "core/mesh/tri_mesh2.h"
#include "core/quality/quality.h"

namespace cvtmesh {

// True if flipping the edge at packed slot `slot` = 3t+e is possible (flip2d_possible) and
// raises the minimum quality (measure m, larger = better) of the two triangles by more than
// `margin`.
bool flip2d_improves_quality(const TriMesh2& mesh, int slot, Measure m = Measure::kQ,
                             double margin = 1e-12);

}  // namespace cvtmesh
