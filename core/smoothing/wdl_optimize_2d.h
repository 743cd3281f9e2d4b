// WDL, the weighted Delaunay-Laplacian optimization of Du & Wang (Section 2.2): for a free
// vertex P and each adjacent vertex P_i, the point P_i* on P_i -> P with l(P_i P_i*) = 1 in the
// metric of the sizing field H (l = integral of ds/H, H linear along the edge); P_new = centroid
// of the P_i*; coupled with Delaunay edge flips, to convergence.
#pragma once
#include "core/smoothing/smooth2d.h"

namespace cvtmesh {

// See smooth_optimize_2d (core/smoothing/smooth2d.h); options.sizing is the metric.
LloydResult wdl_optimize_2d(TriMesh2& mesh, const Smooth2dOptions& options = {},
                            const std::function<void(const LloydStep&)>& progress = nullptr);

}  // namespace cvtmesh
