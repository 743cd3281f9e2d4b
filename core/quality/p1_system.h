// The P1 finite-element matrices of a mesh for the Laplacian / wave equation: the stiffness K
// (sum over the live elements of volume * grad phi_i . grad phi_j) in compressed rows, the
// row-sum lumped mass (volume / #vertices to each vertex of an element) and which vertices lie on
// the domain boundary (on a face -- an edge in 2D -- of exactly one live element). Vertices of
// no live element have mass 0 and an empty row. Inputs of explicit_time_step.h and
// poisson_cg.h.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

struct P1System {
  int n = 0;                   // #V (all vertices, used or not)
  std::vector<long> row_ptr;   // n+1 offsets into col / val
  std::vector<int> col;        // column of each entry, increasing within a row (diagonal included)
  std::vector<double> val;     // K entries
  std::vector<double> mass;    // n lumped masses
  std::vector<char> boundary;  // n: 1 = on the domain boundary
  long nb_elements = 0;        // live elements assembled
};

// Negatively oriented elements are assembled with their absolute volume (the matrices of a
// valid mesh). The assembly is parallel and its result does not depend on the thread count.
P1System p1_system(const TetMesh& mesh);
P1System p1_system(const TriMesh2& mesh);

// y = K x (x, y: n values). Parallel over the rows.
void p1_multiply(const P1System& s, const std::vector<double>& x, std::vector<double>& y);

}  // namespace cvtmesh
