// CVDT by Lloyd iteration in 3D (Du & Wang, Algorithm 2.1): interior vertices move to the mass
// centroids of their Voronoi cells restricted to their region (clipped by the domain boundary
// and interfaces), under rho = 1/H^5; then the constrained boundary Delaunay tetrahedralization
// of the moved points is rebuilt (Delaunay3 backend). Boundary and interface vertices and
// triangles never move.
#pragma once
#include <functional>
#include <memory>
#include <string>

#include "core/cvt/lloyd.h"
#include "core/cvt/lloyd3_cells.h"  // voronoi_centroids_3d
#include "core/cvt/sizing_field3.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct Lloyd3Options {
  LloydOptions lloyd;
  std::string backend = "tetgen";
  // If null, the input mesh's local edge length (make_mesh_sizing3 on the input).
  std::shared_ptr<const SizingField3> sizing;
  bool compute_energy = true;  // also integrate the cells of the fixed vertices (full energy F)
  // A target centroid whose straight move would leave the region is pulled back towards the
  // vertex (halved up to this many times; the vertex stays put if still outside).
  int max_halvings = 4;
  // Over-relaxation: move to z + omega (c - z). omega = 1 is the paper's Lloyd step; any omega in
  // (0, 2) still decreases the energy for the current partition (|1 - omega| < 1), so the
  // iteration stays monotone, and omega around 1.5-1.8 converges several times faster.
  double relaxation = 1.0;
  // Anderson acceleration depth (0 = plain Lloyd). An accelerated step that raises the energy is
  // undone and replaced by the plain step, so the accepted energies never increase.
  int anderson_depth = 0;
  // L-BFGS on the CVT energy instead of Lloyd's step (Liu et al. 2009, "On centroidal Voronoi
  // tessellation - energy smoothness and fast computation"), with this memory (0 = off; then
  // relaxation/anderson_depth apply). Gradient dF/dz_i = 2 m_i (z_i - c_i), initial inverse
  // Hessian diag(relaxation / (2 m_i)) (the first direction is the relaxed Lloyd step: the CVT
  // Hessian is 2 m_i (I - dc_i/dz_i), so 1 / (2 m_i) underestimates the step), backtracking line
  // search (Armijo on the actual, safeguarded moves; at most 3 trials, then the plain Lloyd step).
  // Every trial is one iteration (one evaluation of the cells); a rejected one reports `restarted`.
  int lbfgs_memory = 0;
  // Re-insertion: restore the constrained Delaunay property by exact Lawson flips on the current
  // mesh after the move (restore_delaunay3.h); rebuild with the backend only when a moved vertex
  // inverted a tet or a non-Delaunay face cannot be flipped. false: always rebuild.
  bool local_flips = true;
  // When the flips leave at most this many vertices short of their targets (relative to #V), or
  // faces they cannot make Delaunay (the mesh is valid either way: every move keeps its star
  // positively oriented), the iteration goes on with that mesh (its cells are clipped where it is
  // not Delaunay) instead of rebuilding (and at the end too: TetGen's rebuild leaves them as well).
  double max_flip_leftover = 0.01;
  // Cell buffers kept by the caller from one run to the next (null: the run's own). The
  // pipeline's Lloyd, constrained CVT and second Lloyd share one: at 10M tets the cell mesh is
  // ~2.5 GB, paged in once instead of at each phase's first evaluation.
  Lloyd3CellBuffers* cell_buffers = nullptr;
};

// Runs the iteration on `mesh` (valid on entry; valid, with the same constrained triangles, on
// exit). Throws InvariantError if an iteration breaks an invariant.
LloydResult lloyd_optimize_3d(TetMesh& mesh, const Lloyd3Options& options,
                              const std::function<void(const LloydStep&)>& progress = nullptr);

}  // namespace cvtmesh
