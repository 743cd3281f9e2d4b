// The paper's perturbed initial meshes (Du & Wang, Section 3): RandPert moves every interior
// vertex randomly, ClusPert pulls the interior vertices towards an attractor (the domain's centre,
// or the boundary of a hole). The mesh is then re-triangulated (constrained Delaunay), so every
// triangle stays valid.
#pragma once
#include <string>

#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

enum class Perturbation2d {
  kRandom,   // RandPert: z += amount * h_z * u, u uniform in the unit disk
  kCluster,  // ClusPert: z = a + (1 - amount) * (z - a), a = attractor point for z
};

struct Perturb2dOptions {
  Perturbation2d kind = Perturbation2d::kRandom;
  unsigned seed = 1;
  // Random: radius of the moves relative to the local edge length h_z (mean length of the edges
  // at z). Cluster: fraction of the distance to the attractor covered (0..1). < 0: the default
  // (0.4 random, 0.5 cluster).
  double amount = -1;
  // Cluster: "centre" (the area centroid of the domain), "hole" (the nearest point on the
  // boundary of a hole: the constrained-edge loops other than the outer one), or "auto" (hole if
  // the domain has one, else centre).
  std::string attractor = "auto";
};

struct Perturb2dResult {
  int nb_moved = 0;
  int nb_limited = 0;     // moves shortened because the target left the surface
  std::string attractor;  // "centre" or "hole" (cluster), "" (random)
};

// Perturbs the free vertices of mesh (vclass dim 2, not on a constrained edge) in place and
// re-triangulates it (cdt2d_remesh). A move whose target is not strictly inside the vertex's
// surface is halved until it is (at most 10 times, else dropped). Deterministic for a seed.
// Throws InputError for an invalid mesh, std::invalid_argument for a bad option.
Perturb2dResult perturb_2d(TriMesh2& mesh, const Perturb2dOptions& options);

}  // namespace cvtmesh
