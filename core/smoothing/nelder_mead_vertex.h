// Derivative-free max-min placement of one vertex within bounds: Nelder-Mead on its star's
// minimum of min(Q, min dihedral angle / angle_scale), the objective of smooth_maxmin3 and
// repair_slivers, with every tet of the star held within absolute bounds at the end: Q at least
// q_floor, its dihedral angles within [angle_floor, angle_ceiling], its element time step at least
// dt_floor. The start may be outside the bounds (a vertex just inserted): positions outside them
// rank below every position inside, by how far outside, so the search first walks into them.
// Where several tets of the star are active at once (a kink of the minimum), the gradient ascent
// of smooth_maxmin3 stops; the simplex walks along the kink (Gmsh t20 after the free boundary: a
// corner tet's star 0.0512 -> 0.0576 where the ascent stopped, docs/reproduction.md "stop 39").
// The move is kept only if the end is within the bounds, every tet of the star positively
// oriented (exact orient3d) and the objective above the start's by min_gain; otherwise the vertex
// goes back. Connectivity never changes; the vertex's class is not checked (the caller picks the
// vertices it may move). Deterministic: a fixed simplex, a fixed number of evaluations at most.
#pragma once
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct NelderMeadVertexOptions {
  double angle_scale = 60;  // degrees: the dihedral angles enter as angle / angle_scale
  double q_floor = 0;       // every tet of the star at the end: Q >= q_floor,
  double angle_floor = 0;   // its dihedral angles within [angle_floor, angle_ceiling] (degrees)
  double angle_ceiling = 180;
  double dt_floor = 0;        // and its element time step >= dt_floor (0: not checked)
  double initial_size = 0.2;  // the first simplex: this fraction of the shortest star edge
  int max_evaluations = 300;
  double min_gain = 1e-4;  // absolute, on the objective
};

struct NelderMeadVertexResult {
  bool moved = false;
  // The star's objective at the start and at the end (below 0: outside the bounds).
  double before = 0, after = 0;
};

// Moves vertex v of mesh within its star (the live tets `star`, `nb` of them, all holding v).
NelderMeadVertexResult nelder_mead_vertex(TetMesh& mesh, int v, const int* star, int nb,
                                          const NelderMeadVertexOptions& options = {});

}  // namespace cvtmesh
