#include "core/smoothing/dl_optimize_2d.h"

namespace cvtmesh {

LloydResult dl_optimize_2d(TriMesh2& mesh, const Smooth2dOptions& options,
                           const std::function<void(const LloydStep&)>& progress) {
  return smooth_optimize_2d(mesh, SmoothMove2d::kLaplacian, options, progress);
}

}  // namespace cvtmesh
