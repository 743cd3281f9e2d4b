#include "core/smoothing/wdl_optimize_2d.h"

namespace cvtmesh {

LloydResult wdl_optimize_2d(TriMesh2& mesh, const Smooth2dOptions& options,
                            const std::function<void(const LloydStep&)>& progress) {
  return smooth_optimize_2d(mesh, SmoothMove2d::kWeighted, options, progress);
}

}  // namespace cvtmesh
