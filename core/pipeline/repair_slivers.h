// Repair of the slivers that smoothing and flips leave (the "boundary-locked" ones: most of their
// vertices on the boundary, a face or two constrained): for each tet below a threshold, worst
// first, composite operations are tried on a local copy of its neighbourhood (local_mesh.h) and
// the best result is committed only if it raises the local minimum:
//   - insertion: a new interior vertex p in the tet's cavity (insert_vertex.h; the cavity never
//     crosses a constrained face), p the best of a few candidates (centroid, circumcentre, the
//     apices of regular tets on the tet's faces, ...), then max-min smoothing (smooth_maxmin3,
//     which moves p and the free vertices around) and Q flips (swap_slivers) on the copy;
//   - composite flip + smooth: an edge removal or 2-3 flip of the tet even if it lowers the local
//     minimum, then the same smoothing and flips;
//   - with to_mesh_extremes (below): the tet's interior vertices moved by a simplex search within
//     the bounds (nelder_mead_vertex.h), which also places the inserted vertex.
// The copy holds the tet, its face neighbours, the rings of its edges and the stars of their free
// vertices, so everything that changes is in it. A result is kept when the minimum over the copy
// of min(Q, min dihedral angle / 60 degrees) rises by min_gain and neither the minimum Q nor the
// minimum dihedral angle of the copy falls: the mesh's minima never decrease (with
// to_mesh_extremes, below: the angles within the mesh's extremes instead). Vertices with
// vclass.dim < 3 never move, constrained triangles never change, every tet stays positively
// oriented (exact orient3d). Serial and in a fixed order: the result depends on the input only.
#pragma once
#include "core/mesh/tet_mesh.h"
#include "core/quality/time_step_guard.h"
#include "core/smoothing/smooth_maxmin3.h"

namespace cvtmesh {

struct RepairOptions {
  // Tets tried: Q below q_below or a dihedral angle below angle_below (degrees).
  double q_below = 0.2;
  double angle_below = 15;
  int max_tets = 64;    // tried per pass at most (the worst first)
  int passes = 2;       // passes over the tets below the thresholds (stops when nothing changes)
  bool insert = true;   // try a vertex insertion
  bool flip = true;     // try the composite flip + smooth
  int max_cavity = 16;  // tets in an insertion's (Bowyer-Watson) cavity at most
  // Required rise of the copy's min(Q, min dihedral angle / 60 degrees).
  double min_gain = 1e-3;
  // The smoothing on the copy (its `passes` per round) and the number of smoothing + flip rounds.
  MaxMinOptions smoothing = [] {
    MaxMinOptions m;
    m.passes = 2;
    return m;
  }();
  int rounds = 2;
  // The last repair's rule (optimize's repair of the worst tets): the angles of what a result
  // changes may go down to the mesh's minimum dihedral angle at the start (not only to their own
  // minimum before) and up to max(their maximum before, min(angle_ceiling, the mesh's maximum at
  // the start)); an inserted vertex, and the interior vertices of the tet tried, are then placed
  // by a simplex search within those bounds (nelder_mead_vertex.h). So the global minimum angle
  // never falls and the maximum never rises, while a tet fixed between locked vertices (the tip
  // of a valence-3 surface vertex, a CAD corner) may take the room the rest of the mesh leaves.
  bool to_mesh_extremes = false;
  double angle_ceiling = 150;  // degrees (to_mesh_extremes)
  // Every (point, cavity) pair of an insertion polished and placed, each judged as a result (not
  // only the pair whose new tets' minimum is the highest before the placement).
  bool every_placement = false;
  // The time-step guard (time_step_guard.h; off by default): a result is also refused when the
  // smallest element time step of the tets it changes falls below min(its value before, floor).
  TimeStepGuard dt_guard;
};

struct RepairStats {
  int passes = 0;
  long nb_tried = 0;                                 // tets tried
  long nb_inserted = 0;                              // committed insertions (= vertices added)
  long nb_flip_smooth = 0;                           // committed composite flips
  double q_min_before = 0, q_min_after = 0;          // global minimum Q
  double angle_min_before = 0, angle_min_after = 0;  // global minimum dihedral angle (degrees)
};

// Repairs mesh in place; builds mesh.adj if needed and leaves it valid, the tets compacted. New
// vertices are appended (vclass {3, region}, node tag 0 if node tags are kept).
// Throws std::invalid_argument for bad options.
RepairStats repair_slivers(TetMesh& mesh, const RepairOptions& options = {});

}  // namespace cvtmesh
