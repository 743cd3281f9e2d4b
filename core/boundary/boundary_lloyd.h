// Constrained CVT of the whole mesh (Du, Gunzburger & Ju's constrained CVT, the boundary side of
// Du & Wang's Lloyd step): each round computes every vertex's Voronoi cell restricted to its
// region (voronoi_centroids_3d, density rho = 1/H^5) and moves
//  - interior vertices to z + omega (c - z) (refused where their star would invert),
//  - surface vertices to the closest point of their surface patch to z + omega (c - z),
//  - curve vertices to the closest point of their curve (a 1D CVT along it),
// never corners, locked or periodic vertices (plan_boundary_move checks each move: exact
// orientation of the star, Hausdorff tolerance). Then the constrained Delaunay property is
// restored by flips. A round that raises the CVT energy is undone and retried with half the step,
// so the accepted energies never increase.
#pragma once
#include <limits>
#include <vector>

#include "core/geometry/boundary_geometry.h"
#include "core/boundary/volume_budget.h"
#include "core/cvt/lloyd3_cells.h"
#include "core/cvt/sizing_field3.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct BoundaryLloydOptions {
  int max_rounds = 10;
  double relaxation = 1.0;  // omega in (0, 2)
  // Stop when the mean squared move of the boundary vertices over the squared mean edge length
  // is below this.
  double tolerance = 1e-5;
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  bool move_interior = true;
  int max_halvings = 2;  // of omega, when a round raised the energy
  // Shape guards on a boundary move: no tet of its star may fall below min(the star's minimum Q
  // before the move, q_guard), no triangle of its fan below min(the fan's minimum Q, tri_guard)
  // (the Lloyd step does not care about shapes, but the flips cannot repair a tet or triangle
  // flattened against the boundary, and TetGen's rebuild fails on near-degenerate facets).
  double q_guard = 0.1;
  double tri_guard = 0.3;
  // And the move of a vertex on one of the input's curves (vclass dim 1) may not raise its star's
  // maximum dihedral angle above max(the maximum before the move, curve_angle_guard) (degrees):
  // where two curves meet at a small angle (t20's CAD corners, ~12 degrees) the 1D CVT along them
  // pulled their vertices into the corner and left flat caps there (max dihedral 170.6) whose Q
  // the q_guard lets through. 180: off.
  double curve_angle_guard = 165;
  // If set, boundary moves are admitted only within this budget (and charged to it).
  VolumeBudget* volume_budget = nullptr;
  // Cell buffers kept by the caller (null: the call's own), shared with the Lloyd runs around it
  // (Lloyd3Options::cell_buffers).
  Lloyd3CellBuffers* cell_buffers = nullptr;
};

struct BoundaryLloydStats {
  int rounds = 0;              // accepted rounds
  int nb_undone = 0;           // rounds undone (energy rose)
  long nb_moved = 0;           // accepted boundary vertex moves, over the accepted rounds
  long nb_refused = 0;         // boundary moves refused by plan_boundary_move
  std::vector<double> energy;  // CVT energy at the start and after each accepted round
  // The Lloyd iteration's D (lloyd3.h: the mean squared move of the interior vertices to their
  // centroids, relative to H) of the mesh returned: below the Lloyd tolerance, a Lloyd run after
  // this one would stop after its first iteration.
  double interior_D = 0;
};

// mesh: valid, adjacency built; valid (compacted, constrained triangles kept by vertex ids and
// tags) on exit. Throws std::invalid_argument for bad options.
BoundaryLloydStats boundary_lloyd(TetMesh& mesh, const BoundaryModel& model,
                                  const SizingField3& sizing,
                                  const BoundaryLloydOptions& options = {});

}  // namespace cvtmesh
