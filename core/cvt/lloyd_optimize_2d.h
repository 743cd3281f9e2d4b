// Lloyd's iteration in 2D (Du & Wang, Algorithm 2.1): the free vertices move to the mass
// centroids of their Voronoi cells clipped to the domain, and the mesh is rebuilt as the
// constrained Delaunay triangulation of the new positions. Runs in the generic lloyd_iterate.
#pragma once
#include <functional>
#include <vector>

#include "core/cvt/lloyd.h"
#include "core/cvt/sizing_field2d.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

struct Lloyd2dOptions {
  LloydOptions lloyd;           // max_iterations, tolerance on the normalised D
  SizingField2dOptions sizing;  // density rho = 1/H^4 (uniform: rho = 1), and h_i in D
  // Over-relaxation: move to z + omega (c - z); 1 is the paper's step. Any omega in (0, 2)
  // still lowers the energy for the current partition.
  double relaxation = 1.0;
  // Anderson acceleration depth (0 = plain Lloyd, the paper's). An accelerated step that raises
  // the energy is undone and replaced by the plain step (LloydStep::restarted): the accepted
  // energies never increase.
  int anderson_depth = 0;
  // L-BFGS on F instead of Lloyd's fixed-point step (Liu et al. 2009) with this many memory
  // pairs (0 = Lloyd). relaxation and anderson_depth are then not used.
  int lbfgs_memory = 0;
  int max_halvings = 10;  // safeguard: halvings of a move whose target leaves the surface
  // Basin hopping (a global minimisation of the same CVT energy): after the minimiser (Lloyd or
  // L-BFGS) has converged, `hops` times: move every free vertex of the best configuration so far
  // by a random vector uniform in the disk of radius hop_amount * H (halved while it leaves the
  // surface), run the minimiser again, and keep the result if it converged and its CVT energy F
  // is lower. Only F decides. 0 = no hopping (the paper's Lloyd).
  int hops = 0;
  double hop_amount = 0.3;
  unsigned hop_seed = 1;
};

// What lloyd_optimize_2d reached (energies F of the final meshes, exact for uniform rho).
struct Lloyd2dReport {
  double lloyd_energy = 0;  // F after the first run of the minimiser (before any hop)
  int lloyd_iterations = 0;
  double energy = 0;  // F of the returned mesh (<= lloyd_energy)
  int hops = 0, hops_accepted = 0;
  std::vector<double> hop_energies;  // F reached after each hop
};

// mesh: a valid planar mesh (check_mesh ok; adjacency built), optimized in place. Free vertices
// are those classified inside a surface (vclass dim 2) and not on a constrained edge; every other
// vertex keeps its exact coordinates, and the constrained edges and surfaces are kept. A move is
// shortened (halved, up to max_halvings times, else dropped; LloydStep::nb_limited) when its target
// is not strictly inside the vertex's own surface. LloydStep::energy is F over all cells (fixed
// vertices included) before the move; D = (1/k) sum |z_i - z*_i|^2 / H(z_i)^2 over the k free
// vertices. Throws InputError for an invalid input mesh, InvariantError if a step breaks the mesh.
LloydResult lloyd_optimize_2d(TriMesh2& mesh, const Lloyd2dOptions& options = {},
                              const std::function<void(const LloydStep&)>& progress = nullptr,
                              Lloyd2dReport* report = nullptr);

}  // namespace cvtmesh
