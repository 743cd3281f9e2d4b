#include "core/pipeline/optimize.h"

#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>

#include "core/cvt/lloyd3.h"
#include "core/cvt/sizing_field3.h"
#include "core/pipeline/combined_optimize.h"
#include "core/pipeline/methods3.h"
#include "core/pipeline/option_schema.h"
#include "core/pipeline/optimize2d.h"
#include "core/pipeline/repair_slivers.h"
#include "core/swap/swap_slivers.h"
#include "core/pipeline/verify_mesh.h"
#include "core/quality/quality_stats.h"
#include "core/util/error.h"
#include "core/util/thread_count.h"

namespace cvtmesh {
namespace {

std::shared_ptr<const SizingField3> sizing3(const TetMesh& mesh, const OptimizeOptions& o) {
  if (o.sizing == "mesh")
    return std::shared_ptr<const SizingField3>(make_mesh_sizing3(mesh).release());
  if (o.sizing == "uniform")
    return std::shared_ptr<const SizingField3>(
        make_uniform_sizing3(mean_edge_length(mesh)).release());
  if (o.sizing == "function") {
    if (!o.size_function) throw std::invalid_argument("sizing 'function' needs a size_function");
    return std::shared_ptr<const SizingField3>(
        make_function_sizing3(o.size_function, 1e-4 * mean_edge_length(mesh)).release());
  }
  throw std::invalid_argument("unknown sizing '" + o.sizing +
                              "' (expected mesh, uniform or function)");
}

void report(const OptimizeOptions& o, const std::string& phase, int it, double D, double energy,
            const QualityStats& s, bool restarted = false) {
  if (!o.progress) return;
  OptimizeProgress p;
  p.phase = phase;
  p.iteration = it;
  p.D = D;
  p.energy = energy;
  p.q_min = s.q_min;
  p.q_avg = s.q_avg;
  p.restarted = restarted;
  o.progress(p);
}

}  // namespace

// Lloyd to a CVDT (3D).
void run_cvdt3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r) {
  Lloyd3Options lo;
  lo.lloyd.max_iterations = o.max_iterations;
  lo.lloyd.tolerance = o.tolerance;
  lo.relaxation = o.relaxation;
  lo.anderson_depth = o.anderson_depth;
  lo.lbfgs_memory = o.lbfgs_memory;  // resolved: 5 for the default -1
  lo.sizing = sizing3(mesh, o);
  const auto t0 = std::chrono::steady_clock::now();
  const LloydResult lr = lloyd_optimize_3d(mesh, lo, [&](const LloydStep& s) {
    r.lloyd_energy.push_back(s.energy);
    if (o.progress) o.progress(lloyd_progress(s, "lloyd", quality_stats(mesh, "")));
  });
  r.seconds_lloyd = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.iterations = lr.iterations;
  r.converged = lr.converged;
}

// SWAP (Du & Wang): edge removals and 2-3 flips raising the local minimum Q, to convergence.
void run_swap3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r) {
  SwapOptions so;
  so.measure = Measure::kQ;
  so.quality_threshold = o.swap_below;
  const SwapStats st = swap_slivers(mesh, so);
  r.iterations += st.passes;
  r.converged = true;
  report(o, "swap", st.passes, 0, 0, quality_stats(mesh, ""));
}

// The paper's CVDT + SWAP.
void run_cvdt_swap3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r) {
  run_cvdt3(mesh, o, r);
  const int lloyd_iterations = r.iterations;
  const bool lloyd_converged = r.converged;
  run_swap3(mesh, o, r);
  // The method converged when its Lloyd phase did (the swap pass always ends).
  r.iterations = lloyd_iterations;
  r.converged = lloyd_converged;
}

// The classical Combined Optimization (CombOpt).
void run_combined3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r) {
  CombinedOptions co;
  co.max_iterations = o.max_iterations;
  const CombinedStats st = combined_optimize(
      mesh, co, [&](int it, const QualityStats& s) { report(o, "combined", it, 0, 0, s); });
  r.iterations = st.iterations;
  r.converged = st.converged;
}

// The polish: guarded Laplacian passes (never lower a star's minimum Q), max-min smoothing of the
// poor tets (smooth_maxmin3, unless !polish_maxmin) and flips improving the minimal dihedral
// angle that may not lower the minimum Q either, iterated (the CombOpt operators with a Q guard
// on the flips); then the repair of the slivers left (repair_slivers, unless !polish_repair).
void run_polish3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r) {
  CombinedOptions co;
  co.max_iterations = o.max_iterations;
  co.swap.use_guard = true;
  co.swap.guard_measure = Measure::kQ;
  co.swap.guard_floor = o.polish_q_floor;
  co.swap.quality_threshold = o.polish_flip_below;
  // Max-min smoothing of the poor tets' vertices between the Laplacian passes and the flips,
  // and flips that never lower the global minimum Q (the smoothing raised it above the floor).
  co.maxmin = o.polish_maxmin;
  co.maxmin_options.passes = 1;
  co.keep_min_q = o.polish_maxmin;
  const CombinedStats st = combined_optimize(
      mesh, co, [&](int it, const QualityStats& s) { report(o, "smooth", it, 0, 0, s); });
  r.iterations = st.iterations;
  r.converged = st.converged;
  if (o.polish_repair) {
    repair_slivers(mesh, RepairOptions{});
    if (o.progress) report(o, "repair", 1, 0, 0, quality_stats(mesh, ""));
  }
}

// CVDT + SWAP, then the polish (removes near-boundary slivers that flips alone cannot).
void run_cvdt_swap_smooth3(TetMesh& mesh, const OptimizeOptions& o, OptimizeResult& r) {
  run_cvdt_swap3(mesh, o, r);
  const int lloyd_iterations = r.iterations;
  OptimizeResult polish;
  run_polish3(mesh, o, polish);
  r.iterations = lloyd_iterations;
}


OptimizeProgress lloyd_progress(const LloydStep& s, const std::string& phase,
                                const QualityStats& q) {
  OptimizeProgress p;
  p.phase = phase;
  p.iteration = s.iteration;
  p.D = s.D;
  p.energy = s.energy;
  p.q_min = q.q_min;
  p.q_avg = q.q_avg;
  p.restarted = s.restarted;
  p.seconds_cells = s.seconds_cells;
  p.seconds_delaunay = s.seconds_delaunay;
  p.seconds_other = s.seconds_move + s.seconds_check;
  p.nb_dual_cells = s.nb_dual_cells;
  p.nb_clipped_cells = s.nb_clipped_cells;
  p.nb_flips = s.nb_flips;
  p.rebuilt = s.rebuilt;
  p.nb_stuck_faces = s.nb_stuck_faces;
  p.nb_short_moves = s.nb_short_moves;
  return p;
}

OptimizeResult optimize(MeshData& data, const OptimizeOptions& options) {
  // Every front end's values are checked here, against the one option schema.
  validate(options, data.dim);
  // Our thread count for the parallel loops (Gmsh may have set the process's to 1), the caller's
  // back on return.
  const ThreadCountScope threads;
  if (data.dim == 2) return optimize_2d(data.tri, options);
  const OptimizeOptions o = resolve(options, 3);
  OptimizeResult r;
  const auto t0 = std::chrono::steady_clock::now();
  const MethodInfo* method = find_method(o.method, 3);
  r.before = quality_stats(data.tet, "before");
  const TetMesh input = data.tet;
  method->run3(data.tet, o, r);
  if (o.verify) verify_optimized(input, data.tet);
  r.after = quality_stats(data.tet, o.method);
  r.method = o.method;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace cvtmesh
