// The Laplacian-type smoothing loop shared by DL and WDL (Du & Wang, Section 2.2): a
// Gauss-Seidel sweep of vertex moves, then Delaunay edge flips, iterated to convergence in the
// generic loop of core/cvt/lloyd.h. The move is the only difference between the two methods.
#pragma once
#include <functional>

#include "core/cvt/lloyd.h"
#include "core/cvt/sizing_field2d.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

enum class SmoothMove2d {
  kLaplacian,  // DL: P_new = mean of the adjacent vertices P_j
  kWeighted,   // WDL: P_new = mean of the P_j*, P_j* on P_j -> P at unit length in the metric 1/H
};

struct Smooth2dOptions {
  // Iterations (sweep + flip pass) and the stop on D = (1/k) sum |P_new - P|^2 / H(P)^2 over
  // the k free vertices (accepted moves; a rejected move counts as 0).
  LloydOptions loop;
  SizingField2dOptions sizing;  // H: the metric of WDL, and h in D
  bool flips = true;  // Delaunay edge flips after each sweep (DL/WDL); false: smoothing only
};

// mesh: a valid planar mesh, optimized in place. Free vertices: vclass dim 2, not on a
// constrained edge; all others keep their coordinates; constrained edges are never flipped.
// A move that would make an adjacent triangle inverted or flat (exact orient2d) is rejected
// (LloydStep::nb_limited counts them). LloydStep::energy is 0 (no energy is minimized).
// Throws InputError for an invalid input mesh, InvariantError if a step breaks the mesh.
LloydResult smooth_optimize_2d(TriMesh2& mesh, SmoothMove2d move, const Smooth2dOptions& options,
                               const std::function<void(const LloydStep&)>& progress = nullptr);

}  // namespace cvtmesh
