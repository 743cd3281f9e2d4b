// Surface coarsening by boundary edge collapse (issue 13, the femur's average: its surface mesh
// is 1.6x finer than its interior, so the tets standing on it are poor). A surface edge (v, w)
// shorter than `short_fraction` of the interior spacing near v is collapsed by removing v onto
// w (w does not move): the tets around (v, w) vanish, v is replaced by w in the other tets and
// boundary triangles of its star, the two triangles on (v, w) vanish. What MMG does (short-edge
// collapse under a Hausdorff bound).
//
// Check (plan_boundary_collapse), then apply (apply_boundary_collapse); the driver accepts:
//  - v must be a surface vertex of the boundary model (not on a curve, not a corner, not locked,
//    pinned or periodic; or, with fold_vertices, a fold vertex), its star of one region, its
//    boundary triangles all of one surface entity and on the domain's boundary (no interface), its
//    fan a closed disk; w a neighbour on one of those triangles, its star of the same single
//    region;
//  - the link condition (Dey et al., with the boundary coned to a vertex at infinity): the
//    links of v and w meet exactly in the link of (v, w) — no duplicate tet or triangle, each
//    surface keeps its topology (Euler characteristic, boundary edges), the volume its own;
//    some tet of v's star not on (v, w), unless v is a fold vertex (or, with cap_vertices, a cap
//    vertex) standing on one tet whose face opposite v is interior;
//  - every changed tet positive (exact orient3d), the new star's minimum Q and dihedral angle
//    not below min(the old star's minimum, q_floor / angle_floor), the new boundary triangles'
//    Q not below min(the old fan's minimum, tri_floor), each new triangle turning by at most
//    flat_angle from the triangle it replaces, no new edge longer than long_fraction of the
//    interior spacing;
//  - the new triangles' samples within `hausdorff` of the reference boundary, the input
//    position of v and of each vertex of its fan within it of that vertex's new fan;
//  - the volume change (the tets on (v, w) go flat) within the volume budget.
// The removed vertex stays in the arrays, in no element, with role kFixed in the model (it is
// never moved again); the pipeline drops it from the output (core/pipeline/optimize.cpp).
#pragma once
#include <limits>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/volume_budget.h"
#include "core/geometry/boundary_geometry.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {

struct BoundaryCollapseOptions {
  double short_fraction = 0.7;  // collapse edges shorter than this x the interior spacing
  double long_fraction = 1.7;   // no new edge longer than this x the interior spacing
  double q_floor = 0.5;         // new star's min Q >= min(old star's min, q_floor)
  double angle_floor = 30;      // degrees: the same for the minimum dihedral angle
  double tri_floor = 0.5;       // new triangles' Q >= min(old fan's min, tri_floor)
  double flat_angle = 40;       // degrees a new triangle may turn from the one it replaces
  int passes = 10;
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  VolumeBudget* volume_budget = nullptr;
  // A fold vertex may go too (remove_surface_folds.h): a surface or curve vertex of valence 3
  // one of whose triangles is turned over against the other two (each turn above
  // acos(kFoldFloor), about 154 degrees): an input defect. Its curve edges go with it. Off for
  // the coarsening.
  bool fold_vertices = false;
  // A cap vertex may go too (remove_low_step_caps.h): a surface vertex of valence 3 standing on
  // a single tet, its three triangles that tet's faces; the tet goes and its fourth face, interior
  // before, becomes the surface triangle (the nodal step of such a vertex is the tet's height
  // over that face: igl_cheburashka's lowest). A vertex of a curve too where the mesh's model
  // classifies it on a surface (a discrete boundary's feature curve): its two curve edges are
  // replaced by the edge between their other ends. Off for the coarsening.
  bool cap_vertices = false;
};

enum class CollapseCheck {
  kOk = 1,
  kNotSurface = 0,  // v not a surface vertex of one entity / region, or w not its neighbour
  kLink = -1,       // the link condition fails (topology would change)
  kInverted = -2,   // a changed tet would be flat or inverted
  kQuality = -3,    // a tet or triangle below its floor
  kFolded = -4,     // a new triangle turns too far from the one it replaces
  kTooLong = -5,    // a new edge longer than long_fraction x the spacing
  kHausdorff = -6,  // a new triangle or an input vertex leaves the tolerance
  kVolume = -7,     // the volume change does not fit the budget
};

// A planned collapse of v onto w: the tets and triangles that vanish and those where v becomes w.
struct CollapsePlan {
  int v = -1, w = -1;
  bool fold = false;  // v is a fold vertex (BoundaryCollapseOptions::fold_vertices)
  bool cap = false;   // v is a cap vertex (BoundaryCollapseOptions::cap_vertices)
  std::vector<int> kill_tets, move_tets, kill_tris, move_tris;
  std::vector<double> delta;  // per VolumeBudget region (empty without a budget)
};

// Checks the collapse of v onto w (mesh.adj built; star and fans of the current mesh; spacing:
// #V interior spacing, interior_spacing()). Fills plan on kOk; never changes the mesh.
CollapseCheck plan_boundary_collapse(const TetMesh& mesh, const BoundaryModel& model,
                                     const VertexTets& star, const BoundaryFans& fans,
                                     const std::vector<double>& spacing, int v, int w,
                                     const BoundaryCollapseOptions& options, CollapsePlan& plan);

// Kills the tets and triangles on (v, w) (tets[4t] = -1, tris[3f] = -1), writes w for v in the
// others, marks v kFixed in the model, charges the budget. The adjacency, if built, stays valid
// (the dead tets' neighbours glued to each other, their own slots -1); the stars and the fans are
// stale afterwards; the dead triangles must be dropped (compact_boundary_triangles) and the dead
// tets compacted (compact_tets) before the mesh is valid again.
void apply_boundary_collapse(TetMesh& mesh, BoundaryModel& model, const CollapsePlan& plan,
                             VolumeBudget* budget);

// Whether v is a fold vertex (BoundaryCollapseOptions::fold_vertices); `fans` current.
bool is_fold_vertex(const TetMesh& mesh, const BoundaryModel& model, const BoundaryFans& fans,
                    int v);

// Whether v is a cap vertex (BoundaryCollapseOptions::cap_vertices): a movable surface or curve
// vertex of the model with three triangles, all faces of the one tet of its star; `star`, `fans`
// current.
bool is_cap_vertex(const TetMesh& mesh, const BoundaryModel& model, const VertexTets& star,
                   const BoundaryFans& fans, int v);

// Drops the triangles marked dead (tris[3f] < 0) with their surface and element tags.
void compact_boundary_triangles(TetMesh& mesh);

// #V: for each boundary vertex, the mean length of the interior edges (both ends of class dim 3)
// at its interior neighbours; 0 where it has none (and for interior vertices). `star`:
// vertex_tets(mesh), every vertex's (the neighbours' means are summed over their stars, in
// parallel: the same values as one pass over the tets, for any number of threads).
std::vector<double> interior_spacing(const TetMesh& mesh, const VertexTets& star);

struct BoundaryCollapseStats {
  int passes = 0;
  long nb_candidates = 0, nb_tried = 0, nb_collapsed = 0;
};

// Passes over the candidate edges (v surface vertex, |vw| < short_fraction x spacing(v)),
// shortest relative to the spacing first (ties by vertex ids: deterministic), each pass on
// fresh stars, a vertex touched by a collapse left for the next pass; until a pass collapses
// none. On exit the dead tets and triangles are compacted (the adjacency kept valid).
BoundaryCollapseStats collapse_boundary_edges(TetMesh& mesh, BoundaryModel& model,
                                              const BoundaryCollapseOptions& options = {});

}  // namespace cvtmesh
