// The nodal time step of a P1 mesh with lumped mass: for vertex j, dt_j = 2 / sqrt(K_jj / m_j),
// the Rayleigh quotient of the mode that is 1 at j and 0 elsewhere. lambda_max(M_L^-1 K) >= K_jj /
// m_j for every j, so the global explicit time step (explicit_time_step.h) is at most min_j dt_j
// -- and on meshes whose largest mode sits at one vertex (a boundary vertex with flat tets, the
// common case after smoothing) it is nearly equal to it, which the element bound
// (element_time_step.h, a lower bound) does not see. Wave speed 1. Kept per vertex as the sums
// K_jj and m_j over the vertex's tets so that a move or a flip updates them locally
// (time_step_guard.h).
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// The contributions of tet a,b,c,d (3 doubles each) to K_jj of its four vertices (kjj[0..3], in
// the order a,b,c,d) and to the lumped mass of each (|volume| / 4). Zero for a flat tet.
void tet_vertex_terms(const double* a, const double* b, const double* c, const double* d,
                      double kjj[4], double* mass);

struct VertexTimeSteps {
  std::vector<double> kdiag, mass;  // #V sums over the live tets of each vertex
  // 2 / sqrt(kdiag / mass); +inf for a vertex of no tet.
  double dt(int v) const;
};

VertexTimeSteps vertex_time_steps(const TetMesh& mesh);

// The smallest nodal time step of mesh's vertices (+inf for a mesh without tets).
double min_vertex_time_step(const TetMesh& mesh);

}  // namespace cvtmesh
