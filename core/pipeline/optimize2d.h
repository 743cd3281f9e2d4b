// The 2D methods behind optimize() (core/pipeline/optimize.h), on a TriMesh2:
//   "cvdt"       Lloyd's iteration (CVT, constrained Delaunay re-triangulation): lloyd_optimize_2d
//   "cvdt+swap"  the same, then a quality edge-flip pass (min Q of each flipped pair rises)
//   "dl"         Laplacian smoothing + Delaunay flips: dl_optimize_2d
//   "wdl"        edge-length-weighted Laplacian + Delaunay flips: wdl_optimize_2d
#pragma once
#include <string>
#include <vector>

#include "core/mesh/tri_mesh2.h"
#include "core/pipeline/optimize.h"

namespace cvtmesh {

// Optimizes mesh in place with options.method, options.max_iterations, options.tolerance (the
// normalised D of core/cvt/lloyd.h), options.sizing ("mesh": the input's local edge length,
// "uniform": rho = 1, "function": options.size_function), options.relaxation and
// options.anderson_depth (Lloyd only; 1 and 0 give the paper's plain Lloyd), options.lbfgs_memory
// (L-BFGS on the CVT energy instead of Lloyd's step), options.hops,
// options.hop_amount and options.seed (basin hopping after Lloyd; 0 hops = none) and
// options.progress (phase "lloyd", "dl" or "wdl"; q_min/q_avg of the current mesh). With
// options.verify the result is checked against the input (verify_optimized: valid, boundary
// vertices and edges unchanged, areas kept). Fills before/after, iterations, converged, seconds.
// Validates and resolves the options first (option_schema.h): OptionError for a bad value or a
// method that is not a 2D one; InputError for an invalid mesh, InvariantError on a bug.
OptimizeResult optimize_2d(TriMesh2& mesh, const OptimizeOptions& options);

}  // namespace cvtmesh
