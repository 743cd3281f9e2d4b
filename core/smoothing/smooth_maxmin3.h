// Max-min ("optimization-based") smoothing of the worst tets (Freitag & Ollivier-Gooch 1997):
// each interior vertex of a poor tet is moved to raise the minimum quality of its star, by a
// non-smooth ascent on the star's worst functions. The functions of a tet are its Q and its six
// dihedral angles divided by angle_scale; the objective of a star is the minimum of them over its
// tets. A step goes along the smallest vector of the convex hull of the gradients of the (nearly)
// active functions (all of them rise along it), with the step length predicted from where another
// function would become the minimum, halved until the move is accepted. A move is accepted only
// if every tet of the star stays positively oriented (exact orient3d), the objective strictly
// rises, and the guards hold: a tet whose Q (minimum dihedral angle) is at or above a floor stays
// there, one below it does not fall below the star's minimum Q (angle) before the move (see
// MaxMinOptions). The guards are also functions of the ascent, which slides along them. Vertices
// with vclass.dim < 3 never move; connectivity never changes. Serial and in a fixed order: the
// result depends on the input only.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/quality/time_step_guard.h"

namespace cvtmesh {

struct MaxMinOptions {
  // A vertex is optimized when a tet of its star has Q below q_below or a dihedral angle below
  // angle_below (degrees).
  double q_below = 0.5;
  double angle_below = 30;
  // If not null, a flag per tet: only flagged tets count as poor (a local repair).
  const std::vector<char>* only_tets = nullptr;
  // The dihedral angles enter the objective as angle (degrees) / angle_scale; <= 0: Q only.
  double angle_scale = 60;
  // The guards, with floor_eff = max(floor, the mesh's global minimum at the start): moving a
  // vertex never takes a tet of its star from at least floor_eff in Q (minimum dihedral angle)
  // to below it, nor one below it to below the star's minimum before the move. So the global
  // minima never decrease and good tets stay good.
  double q_floor = 0.5;
  double angle_floor = 30;
  // A vertex is moved only if its star's objective rises by at least this much (a small gain is
  // not worth what the star's other tets lose).
  double min_gain = 0.01;
  int passes = 3;      // sweeps over the vertices of the poor tets, worst tet first
  int max_steps = 30;  // ascent steps per vertex and pass
  int max_halvings = 12;
  // The time-step guard (time_step_guard.h; off by default): a move is also refused when the
  // star's smallest element time step falls below min(its value before the move, floor).
  TimeStepGuard dt_guard;
};

struct MaxMinStats {
  int passes = 0;
  long nb_tried = 0;                                 // vertices optimized (over all passes)
  long nb_moved = 0;                                 // of them, moved
  long nb_steps = 0;                                 // accepted ascent steps
  double q_min_before = 0, q_min_after = 0;          // global minimum Q
  double angle_min_before = 0, angle_min_after = 0;  // global minimum dihedral angle (degrees)
};

// Smooths mesh.xyz in place. Dead tets (tets[4t] < 0) are ignored; mesh.adj is not needed.
// The global minimum Q and minimum dihedral angle never decrease; no tet is inverted.
// Throws std::invalid_argument for bad options.
MaxMinStats smooth_maxmin3(TetMesh& mesh, const MaxMinOptions& options = {});

}  // namespace cvtmesh
