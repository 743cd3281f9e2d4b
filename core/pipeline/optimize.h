// The named methods users pick. 3D: cvdt (Lloyd CVDT), cvdt+swap (the paper's CVDT+SWAP),
// cvdt+swap+smooth (CVDT+SWAP then the guarded smoothing + dihedral flips polish), combined (the
// classical CombOpt), swap (flips only), smooth (the polish alone). 2D: cvdt, dl, wdl.
// One entry point for the CLI, the GUI panel and the scripting front ends.
#pragma once
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/boundary/discrete_boundary.h"
#include "core/cvt/lloyd.h"
#include "core/mesh/mesh_data.h"
#include "core/pipeline/method_registry.h"
#include "core/quality/quality_stats.h"
#include "core/quality/worse_than.h"

namespace cvtmesh {

struct OptimizeProgress {
  // "lloyd", "hop N" (2D basin hopping), "swap", "smooth" (the polish), "repair", "bnd-cvt",
  // "combined", "dl", "wdl", "verify".
  std::string phase;
  // The phase begins (a long one: SWAP, the polish, the final checks): no figures yet. The
  // figures of a phase come in reports without it (Lloyd: one per iteration).
  bool start = false;
  int max_iterations = 0;  // Lloyd-type phases: the iteration cap (0 if none)
  double tolerance = 0;    // Lloyd-type phases: the D below which it stops (0 if none)
  int iteration = 0;
  double D = 0;       // Lloyd displacement (normalised), 0 if not applicable
  double energy = 0;  // CVT energy, 0 if not applicable
  double q_min = 0, q_avg = 0;
  bool restarted = false;  // an accelerated Lloyd step was undone (energy rose)
  // Lloyd (3D): wall seconds of this iteration's cells and Delaunay rebuild, and how many cells
  // came from the exact Delaunay dual vs clipping.
  double seconds_cells = 0, seconds_delaunay = 0, seconds_other = 0;
  int nb_dual_cells = 0, nb_clipped_cells = 0;
  int nb_flips = 0;                            // Delaunay restored by this many flips...
  bool rebuilt = false;                        // ...or the tetrahedralization rebuilt
  int nb_stuck_faces = 0, nb_short_moves = 0;  // what the flips left (LloydStep)
};

// Rows closer than this are the same to auto_refine's comparison of two results (differences
// below what the tables show or matter: the femur's 1.5 run, Q_min 0.3865 -> 0.5103, was refused
// for a min dihedral 30.03 -> 30.03 degrees lower in its third decimal).
inline constexpr RowTolerance kAutoRefineTolerance{0.01, 0.001, 0.1};

struct OptimizeOptions {
  std::string method = "cvdt+swap+smooth";
  // Lloyd / outer iterations; -1: the dimension's default (resolve(): 100 in 3D, 1000 in 2D).
  int max_iterations = -1;
  // Lloyd stop on the normalised D (see core/cvt/lloyd.h); -1: the dimension's default (1e-5 in
  // 3D; 1e-8 in 2D, where Lloyd's moves stay small long before the mesh settles: the washer
  // from ClusPert stopped at avg Q 0.976, min angle 36.4° at 1e-5, 0.990 / 42.0° at 1e-8).
  double tolerance = -1;
  double relaxation = 1.5;  // Lloyd over-relaxation omega in (0, 2); 1 = the paper's plain step
  int anderson_depth = 5;   // Anderson acceleration of Lloyd (0 = off: the paper's plain Lloyd)
  // 2D CVT only (refused in 3D): basin hopping on the CVT energy after Lloyd has converged
  // (Lloyd2dOptions::hops): `hops` random kicks of radius hop_amount * H, each followed by Lloyd
  // to convergence, keeping the configuration of lowest energy; random stream from `seed`.
  int hops = 0;
  double hop_amount = 0.3;
  // CVT (2D and 3D): minimise the CVT energy by L-BFGS with this memory instead of Lloyd's step
  // (Lloyd2dOptions / Lloyd3Options::lbfgs_memory; 0 = Lloyd, then relaxation/anderson_depth
  // apply; relaxation also scales L-BFGS's initial inverse Hessian). -1 = the dimension's
  // default: L-BFGS(5) in 3D (fewest iterations, best quality measured), Lloyd in 2D.
  int lbfgs_memory = -1;
  // Sizing field H for the density rho = 1/H^(d+2): "mesh" (the input's local edge length,
  // keeps the user's grading; for a model Gmsh meshed from a .geo that is the model's own mesh
  // sizes), "uniform" (constant), "function" (size_function below), or the path of a reference
  // file (a mesh, or a model Gmsh meshes: a .geo): the local edge length of sizing_reference.
  std::string sizing = "mesh";
  std::function<double(const double* x)> size_function;  // x has d coordinates
  // sizing = a path: that file's mesh, read by the front end (core/io/read_sizing_reference.h),
  // of the dimension of the mesh optimized. Used as a frozen background mesh.
  std::shared_ptr<const MeshData> sizing_reference;
  // The smooth polish's dihedral flips may lower a tet's Q, but never below min(its old
  // minimum, this floor).
  double polish_q_floor = 0.4;
  // SWAP tries only the tets whose Q is below this (+inf: all; the paper's SWAP removes "the very
  // bad elements"). A swap is accepted when it raises its cavity's minimum, so a cavity whose
  // worst tet is above 0.7 gains little; trying every tet took 3x the time for the same minima
  // (stop 25, `cvtmesh optimize X --method cvdt+swap --swap-below inf|0.7`: a 1M CVDT 9.3 -> 2.9 s,
  // Q_min 0.174 / min dihedral 10.1 degrees both, avg 0.8793 -> 0.8797; cube_sphere 25k / x0.995,
  // femur: the same Q_min and dihedral, avg +0.0003). The default pipeline with 0.7 (polish after
  // it): femur h x 1 / 0.99 / 1.01 avg 0.8527 / 0.8543 / 0.8539, Q_min 0.377 / 0.438 / 0.390;
  // cube_sphere x 1 / 0.995 / 0.996 Q_min 0.533 / 0.515 / 0.513; --fix-boundary the same within
  // the runs' scatter (stop 24 had found the polish's Q_min lower after 0.7; no longer).
  double swap_below = 0.7;
  // The polish's dihedral-angle flips try only tets whose minimal dihedral angle (degrees) is
  // below this (+inf: all; cube_sphere 25k: 2.2x slower, min dihedral 26.8 instead of 26.4).
  double polish_flip_below = 45;
  // The polish also moves the vertices of its poor tets (Q < 0.5 or a dihedral angle < 30
  // degrees) to maximise the minimum quality of their stars (core/smoothing/smooth_maxmin3.h).
  bool polish_maxmin = true;
  // The polish's main criterion (issue 16): "quality" (Q and the dihedral angles, the default) or
  // "dt", the element explicit time step (core/quality/element_time_step.h): the Laplacian passes
  // refuse moves that lower a star's smallest step, the flips maximise the ring's smallest step
  // (still never lowering Q below polish_q_floor), the max-min smoothing and the repair keep
  // their Q objective under the strict time-step guard.
  std::string objective = "quality";
  // The polish's time-step guard (core/quality/time_step_guard.h): its moves, flips and repairs
  // never lower the smallest element time step of a star / ring / local copy below min(its old
  // value, polish_dt_floor x the mesh's smallest element step at the start of the iteration).
  bool polish_dt_guard = true;
  double polish_dt_floor = 1.05;
  // The polish ends with the repair of the slivers it left (Q < 0.2 or a dihedral angle < 15
  // degrees, most often locked by the boundary): a new interior vertex or a flip, each followed
  // by local max-min smoothing and flips, kept only where the local minimum rises
  // (core/pipeline/repair_slivers.h). May add interior vertices.
  bool polish_repair = true;
  // Boundary optimization (issue 13; core/boundary/): with the default method cvdt+swap+smooth the
  // surface vertices move on their surface patches, the curve vertices along their curves
  // (corners never), by a constrained CVT after Lloyd and a boundary max-min in the polish. The
  // other methods always keep the boundary fixed (the paper's columns). fix_boundary = true gives
  // the fixed-boundary pipeline, output byte-identical to before the option existed.
  bool fix_boundary = false;
  // Two-sided Hausdorff bound (absolute, model units) between the new boundary and the input's;
  // 0: 2e-3 of the input's bounding-box diagonal.
  double hausdorff = 0;
  // Sharp features of a discrete boundary: a turn above this many degrees across an edge.
  double feature_angle = 40;
  // Free boundary, discrete geometry: Gmsh curves and points across which the surface is smooth
  // (below feature_angle) are not kept (BoundaryModelOptions::free_smooth_curves).
  bool free_smooth_curves = false;
  // Physical groups (by name) whose surfaces / curves stay fixed.
  std::vector<std::string> lock_physical;
  // Relative bound on each region's volume change with a free boundary (checked at the end).
  double volume_tolerance = 5e-3;
  // Constrained-CVT rounds of the boundary after Lloyd (core/boundary/boundary_lloyd.h).
  int boundary_lloyd_rounds = 10;
  // Free boundary: passes of the average-quality smoothing at the end of the run (every vertex,
  // the boundary ones on their entity: core/boundary/smooth_mean_quality.h), each between flips
  // accepted on the average (swap_slivers' sum_criterion); 0 = none. 2 since the surface
  // coarsening (the femur: avg Q 0.8487 with one pass, 0.8517 with two, for 0.2 s).
  int mean_passes = 2;
  // Free boundary: surface coarsening by boundary edge collapse after the first Lloyd
  // (core/boundary/collapse_boundary_edges.h): a surface edge shorter than this fraction of the
  // interior spacing near it is collapsed (its surface vertex removed), under the Hausdorff
  // bound and the volume budget; 0 = none. Not on an order-2 or periodic input.
  double coarsen_surface = 0.7;
  // Interior refinement before Lloyd (the methods that rebuild the tetrahedralization: cvdt*):
  // TetGen's quality bound, Steiner points at the circumcentres of the tets whose circumradius
  // exceeds this times their shortest edge, none on the boundary (core/delaunay/
  // refine_interior3.h); 0 = none. For an Init with too few interior vertices (a coarse model).
  double refine_interior = 0;
  // With refine_interior = 0 and the default method on a coarse model (at most
  // auto_refine_max_tets tets) whose result misses the quality targets (average Q 0.85, Q_min
  // 0.40): the run is repeated with refine_interior 1.5, then (while the targets are missed)
  // 1.2; a result no worse on any quality row than the plain run's (Q_min, min and max dihedral
  // angle, average Q, up to kAutoRefineTolerance) or better on balance (better_on_balance: both Q
  // rows better, a little of an angle row given up), better on Q_min or the average and never
  // worse than the input is kept, of two such the one with the higher average (the notes say
  // which; the element count grows); after a kept 1.2 run, a 1.1 run judged the same way against
  // that run instead of the plain one.
  bool auto_refine = true;
  int auto_refine_max_tets = 200000;
  // Wall-clock seconds the caller allows optimize() (0 = no bound; the CLI sets it from
  // --time-limit): an optional run (auto_refine's) is not started when, at the pace of the run
  // before it, it would end past the bound. Not a user option of the schema.
  double time_budget = 0;
  // The reference geometry of a free boundary: null, or a function returning a model without
  // geometry = the input's own boundary triangulation (make_discrete_boundary); the front ends
  // with the CAD loaded pass make_gmsh_cad_boundary_if_cad (core/io/gmsh_cad_boundary.h).
  std::function<BoundaryModel(const TetMesh&, const BoundaryModelOptions&)> boundary_model;
  // Selection (3D): optimize only these volumes, by entity tags ("1,3") and/or a volume physical
  // group's name; "" = not given (both empty: every volume). The other volumes' vertices and tets
  // are kept exactly, and the selection's boundary, the interface with them included, is fixed
  // (core/pipeline/select_regions.h, core/mesh/extract_regions.h).
  std::string regions;
  std::string physical;
  unsigned seed = 0;
  bool verify = true;  // run the invariant checks at the end (throws InvariantError)
  // Never worse than the input: if the method's result has a lower Q_min or minimum angle
  // (dihedral in 3D) or a higher maximum angle, the vertices around the elements short of the
  // input's worst go back to their input positions first (per region:
  // core/pipeline/restore_worse_regions.h); if that is not enough, or the method fails to finish
  // (a failure of the Delaunay rebuild), the polish alone (local, guarded operations: "smooth")
  // is tried on the input, with the same per-region restore, and if that is worse too the input
  // is returned unchanged (in 2D the input at once). OptimizeResult::notes says which.
  bool never_worse = true;
  // Coordinates are verified as a text writer stores them: the moved and new vertices are rounded
  // to this many significant digits, and every tet must stay positive with all coordinates
  // rounded (16: Gmsh's ASCII .msh; our writers use 17). 0 = full precision.
  int output_digits = 16;
  // Before a method that rebuilds the tetrahedralization (cvdt*: TetGen), the boundary is
  // checked for self-intersections and coincident nodes (find_structural_defects.h); with
  // defects the local operations alone run ("smooth") and the notes say where the defect is.
  // Nodes closer than this fraction of the bounding-box diagonal count as coincident.
  double coincident_tolerance = 1e-8;
  std::function<void(const OptimizeProgress&)> progress;
};

struct OptimizeResult {
  QualityStats before, after;
  int iterations = 0;
  bool converged = false;
  double seconds = 0;
  std::string method;  // the method that ran (a 3D default name maps to "cvdt" in 2D)
  // 3D Lloyd phase: the energy before each iteration's move, and where its time went.
  std::vector<double> lloyd_energy;
  // Each Lloyd iteration's own time (its cells, Delaunay flips, moves and checks; not the phase's
  // set-up), in the order they ran.
  std::vector<double> lloyd_iteration_seconds;
  double seconds_lloyd = 0;
  // Free boundary (empty when the boundary was fixed): measured at the end of the run.
  bool boundary_free = false;
  int nb_boundary_moved = 0;    // boundary vertices that moved
  int nb_boundary_removed = 0;  // surface vertices removed (coarsen_surface, remove_surface_folds)
  int nb_folds_removed = 0;     // of which the input's surface folds (remove_surface_folds)
  // Roles of the boundary vertices: on a surface patch, on a curve, fixed (corners, locked).
  int nb_surface_vertices = 0, nb_curve_vertices = 0, nb_fixed_vertices = 0;
  double hausdorff = 0;            // two-sided Hausdorff distance new vs input boundary
  double hausdorff_tolerance = 0;  // the bound it was held to
  double diagonal = 0;             // the input's bounding-box diagonal
  double volume_change = 0;        // largest relative change of a region's volume
  double tri_q_min_before = 0, tri_q_min_after = 0;  // worst boundary triangle Q
  std::string boundary_geometry;  // the reference geometry's kind: "discrete" or "cad"
  // What optimize() did besides the method: a fallback to local operations (structural
  // defects), the input kept where the method would have made it worse, elements kept
  // unchanged, ... One sentence each, for the summary.
  std::vector<std::string> notes;
  bool kept_input = false;  // the input is returned unchanged (see notes)
  // Vertices moved back to their input positions around elements the method left worse than
  // the input's worst (the per-region never-worse: restore_worse_regions; see notes).
  long nb_restored = 0;
};

// Optimizes data in place (every tet region in 3D, every surface in 2D; boundary and interfaces
// kept exactly). The options are checked first against the option schema
// (core/pipeline/option_schema.h: validate, then resolve): OptionError (an InputError) for a bad
// value, an unknown method or one that does not apply to the mesh's dimension; InputError for a
// mesh it cannot handle, InvariantError on a bug.
OptimizeResult optimize(MeshData& data, const OptimizeOptions& options);

// The progress report of one Lloyd-type iteration (2D or 3D) in `phase`, with the mesh's quality q.
OptimizeProgress lloyd_progress(const LloydStep& s, const std::string& phase,
                                const QualityStats& q);

}  // namespace cvtmesh
