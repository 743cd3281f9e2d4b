// Removal of boundary caps (issue 13, item 3: the one-tet surface flip). A cap is a tet (a, b, c,
// d) whose faces (a, b, c) and (a, b, d) are boundary triangles of one surface entity and whose two
// other faces (a, c, d), (b, c, d) are interior (neighbours of the same region): a thin tet lying
// on the surface, which no vertex move can fix (its four vertices are on the surface). Removing it
// flips the surface edge (a, b) to (c, d): the two triangles become (a, c, d) and (b, c, d), with
// their surface tag (and element tags) kept; the domain loses the cap's volume.
//
// Check (plan_cap_removal), then apply (apply_cap_removal); the driver accepts:
//  - refused when (a, b) may be a curve (BoundaryModel::may_be_curve_edge), when the two triangles
//    are not of one surface or turn by more than flat_angle, when (c, d) is already an edge of a
//    boundary triangle (the surface would stop being a manifold), when a neighbour is missing, of
//    another region or across a constrained face, when a new triangle's samples leave the
//    Hausdorff tolerance or an input vertex of a, b, c, d is no longer within it of its new fan,
//    when the volume change does not fit the volume budget;
//  - kept only if the local minimum rises by min_gain: over the cap's min(Q, min dihedral / 60
//    degrees), its two neighbours' and the two old triangles' Q before; the neighbours' and the
//    two new triangles' Q after.
// Every vertex stays where it is and on the boundary; each surface keeps its number of triangles,
// its vertices and its topology (an edge flip of a triangulated patch). On exit the dead tets are
// compacted and the adjacency rebuilt.
#pragma once
#include <limits>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/volume_budget.h"
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {

struct CapRemovalOptions {
  double cap_below = 0.5;  // try the caps whose min(Q, min dihedral / 60) is below this
  double flat_angle = 35;  // degrees between the two old triangles' normals, at most
  double min_gain = 1e-3;
  int passes = 2;
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  VolumeBudget* volume_budget = nullptr;
};

// A planned removal: the cap, its two boundary triangles (f1 = (a, b, c), f2 = (a, b, d)) and the
// volume change per budget region.
struct CapPlan {
  int tet = -1, f1 = -1, f2 = -1;
  int a = -1, b = -1, c = -1, d = -1;
  double old_min = 0, new_min = 0;
  std::vector<double> delta;  // per VolumeBudget region (empty without a budget)
};

enum class CapCheck {
  kOk = 1,
  kNotACap = 0,       // not two boundary faces of one surface with two interior neighbours
  kCurve = -1,        // (a, b) may lie on a curve
  kNotFlat = -2,      // the two triangles turn by more than flat_angle
  kNonManifold = -3,  // (c, d) is already an edge of the surface
  kNoGain = -4,       // the local minimum would not rise
  kHausdorff = -5,    // a new triangle or an input vertex leaves the tolerance
  kVolume = -6,       // the volume change does not fit the budget
  kFolds = -7,        // the new triangles would fold the surface (surface_folds.h)
};

// Checks the removal of tet t (live; mesh.adj built; star and fans of the current mesh). Fills
// plan on kOk; never changes the mesh.
CapCheck plan_cap_removal(const TetMesh& mesh, const BoundaryModel& model, const VertexTets& star,
                          const BoundaryFans& fans, int t, const CapRemovalOptions& options,
                          CapPlan& plan);

// Kills the cap (tets[4t] = -1) and retargets its two triangles; charges the budget. The
// adjacency, if built, stays valid (the faces behind the cap's become boundary faces); the stars
// are stale afterwards (the driver compacts).
void apply_cap_removal(TetMesh& mesh, const CapPlan& plan, VolumeBudget* budget);

struct CapRemovalStats {
  int passes = 0;
  long nb_tried = 0, nb_removed = 0;
};

// Worst caps first, each pass on fresh stars, until a pass removes none.
CapRemovalStats remove_boundary_caps(TetMesh& mesh, const BoundaryModel& model,
                                     const CapRemovalOptions& options = {});

}  // namespace cvtmesh
