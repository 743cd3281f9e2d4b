// DL, the Delaunay-Laplacian optimization of Du & Wang (Section 2.2): Laplacian smoothing
// (P_new = mean of the adjacent vertices) coupled with Delaunay edge flips, to convergence.
#pragma once
#include "core/smoothing/smooth2d.h"

namespace cvtmesh {

// See smooth_optimize_2d (core/smoothing/smooth2d.h); options.sizing only scales D.
LloydResult dl_optimize_2d(TriMesh2& mesh, const Smooth2dOptions& options = {},
                           const std::function<void(const LloydStep&)>& progress = nullptr);

}  // namespace cvtmesh
