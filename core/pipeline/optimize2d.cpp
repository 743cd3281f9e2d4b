#include "core/pipeline/optimize2d.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "core/cvt/lloyd_optimize_2d.h"
#include "core/pipeline/option_schema.h"
#include "core/pipeline/verify_mesh.h"
#include "core/smoothing/dl_optimize_2d.h"
#include "core/smoothing/wdl_optimize_2d.h"
#include "core/swap/flip2d_pass.h"
#include "core/util/error.h"

namespace cvtmesh {

OptimizeResult optimize_2d(TriMesh2& mesh, const OptimizeOptions& given) {
  validate(given, 2);
  const OptimizeOptions options = resolve(given, 2);
  const std::string& method = options.method;
  const auto t0 = std::chrono::steady_clock::now();
  OptimizeResult r;
  r.before = quality_stats(mesh, "before");
  const TriMesh2 input = mesh;

  SizingField2dOptions sizing;
  sizing.kind = options.sizing;
  sizing.function = options.size_function;
  if (sizing_is_path(options)) {  // validate() checked that a 2D reference was read
    sizing.kind = "mesh";
    sizing.background = &options.sizing_reference->tri;
    // A mesh's vertex sizes are noisy where it follows a smooth size field: smoothed (20 passes:
    // on the washer from ClusPert, 0 passes ended at Q_min 0.832 fully converged, 20 at 0.880;
    // docs/reproduction-2d.md, "The washer through the CLI").
    sizing.smoothing_passes = 20;
  }
  LloydOptions loop;
  loop.max_iterations = options.max_iterations;
  loop.tolerance = options.tolerance;
  const std::string phase = method == "dl" ? "dl" : method == "wdl" ? "wdl" : "lloyd";
  std::function<void(const LloydStep&)> progress;
  if (options.progress)
    progress = [&](const LloydStep& s) {
      OptimizeProgress p = lloyd_progress(s, s.hop > 0 ? "hop " + std::to_string(s.hop) : phase,
                                          quality_summary(mesh, ""));
      p.max_iterations = options.max_iterations;
      p.tolerance = options.tolerance;
      options.progress(p);
    };

  LloydResult lr;
  if (phase == "lloyd") {
    Lloyd2dOptions lo;
    lo.lloyd = loop;
    lo.sizing = sizing;
    lo.relaxation = options.relaxation;
    lo.anderson_depth = options.anderson_depth;
    lo.lbfgs_memory = options.lbfgs_memory;  // resolved: 0 for the default -1
    lo.hops = options.hops;
    lo.hop_amount = options.hop_amount;
    lo.hop_seed = options.seed;
    lr = lloyd_optimize_2d(mesh, lo, progress);
    if (method == "cvdt+swap") flip2d_pass(mesh, {.criterion = FlipCriterion2d::kQuality});
  } else {
    Smooth2dOptions so;
    so.loop = loop;
    so.sizing = sizing;
    lr = phase == "dl" ? dl_optimize_2d(mesh, so, progress) : wdl_optimize_2d(mesh, so, progress);
  }
  if (options.verify && options.progress) {
    OptimizeProgress p;
    p.phase = "verify";
    p.start = true;
    options.progress(p);
  }
  if (options.verify) verify_optimized(input, mesh);
  r.after = quality_stats(mesh, method);
  r.iterations = lr.iterations;
  r.converged = lr.converged;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.method = method;
  return r;
}

}  // namespace cvtmesh
