// gmsh_optimize: optimizes the mesh of the CURRENT Gmsh model of this process in place — the
// entry point of in-process scripting (C++ and the Python module `cvtmesh`) and of the GUI panel.
// Reads the mesh through the SDK, optimizes every volume (3D), every planar surface (2D) or the
// surfaces in space of a model without volumes (a surface mesh in space, on their CAD), writes
// nodes and elements back into the same model (entities, physical groups and lower-dimensional
// elements intact) and optionally adds per-element quality views. A free boundary (the default
// method) moves on the model's CAD surfaces and curves where it has them
// (make_gmsh_cad_boundary_if_cad, unless options.optimize.boundary_model is set), on the mesh's
// own boundary triangulation otherwise (a discrete model, a merged .msh).
//
// The caller owns Gmsh: it called gmsh::initialize() (Python: gmsh.initialize()) and loaded a
// model. These functions declare it to the rest of cvtmesh (set_gmsh_initialized_by_caller(true),
// core/io/gmsh_session.h), so that nothing of ours initializes or finalizes that Gmsh; a program
// that finalizes Gmsh and then uses cvtmesh's file I/O must set it back to false.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/mesh_data.h"
#include "core/pipeline/optimize.h"
#include "core/quality/fe_measures.h"
#include "core/quality/quality_table.h"

namespace cvtmesh {

struct GmshOptimizeOptions {
  OptimizeOptions optimize;    // method, iterations, tolerance, sizing, seed, progress; an
                               // empty method: the first of methods_for_dim(mesh dimension)
  int dim = -1;                // 3: volumes, 2: planar surfaces, -1: highest dimension meshed
  bool generate = false;       // mesh the model first (gmsh generate(model dim)) if it has no mesh
  bool quality_views = false;  // add ElementData views (Q, radius ratio, min angle) on the result
                               // (its triangles or tets; none for a mesh of quadrangles only)
  // The FE measures of the statistics (core/quality/fe_measures.h): gmsh_quality's, and
  // gmsh_optimize's before and after.
  FeOptions fe;
};

struct GmshOptimizeResult {
  OptimizeResult result;  // before/after statistics, iterations, converged, seconds
  std::string method;
  int dim = 0;
  // dim 3 without tets: a surface mesh in space (its elements are triangles).
  bool surface_mesh = false;
  std::vector<int> views;  // tags of the quality views added (empty unless asked for)

  // The paper's table: column "Init" (before) and the method's column (after, with the rows
  // iterations, converged and seconds).
  QualityTable table() const;
  // {"method", "dim", "surface_mesh", "iterations", "converged", "seconds", "views",
  //  "before": {...}, "after": {...}} with before/after the columns of table().to_json(), and with
  //  a free boundary "free_boundary": {"geometry" ("cad" or "discrete"), "moved", "hausdorff",
  //  ...}.
  std::string to_json() const;
};

GmshOptimizeResult gmsh_optimize(const GmshOptimizeOptions& options = {});

// The tags of the elements the quality views are keyed on: the tets of a volume mesh, the
// triangles of a 2D mesh and of a surface mesh in space (a TetMesh without tets).
std::vector<std::size_t> element_tags_of(const MeshData& data);

// The same in three steps, for a caller that must keep the Gmsh calls in one thread and run the
// optimization in another (the GUI). gmsh_read_current meshes the model first if asked to,
// restores the boundary elements a .msh saved with physical groups lacks (add_missing_facets: they
// are added to the current model) and returns its mesh; gmsh_write_back replaces the current
// model's mesh by data, removes the stale quality views of an earlier run (and the histogram, stale
// or not) and adds new ones if asked to. Gmsh must not be used by anything else between the two
// calls.
MeshData gmsh_read_current(const GmshOptimizeOptions& options);
GmshOptimizeResult gmsh_write_back(const MeshData& data, const OptimizeResult& result,
                                   const GmshOptimizeOptions& options);

// Quality of the current model's mesh without changing it: statistics, and the quality views if
// options.quality_views (those of an earlier run are removed first). Meshes first if asked to.
struct GmshQualityResult {
  QualityStats stats;
  std::vector<int> views;
};
GmshQualityResult gmsh_quality(const GmshOptimizeOptions& options);

// The names of the quality views gmsh_write_back adds for a dimension (2 or 3).
std::vector<std::string> quality_view_names(int dim);

// The name of the quality histogram the GUI and the ONELAB client add after a run (a graph view).
inline const std::string kHistogramViewName = "Q histogram (% of elements)";
// Every view name of ours: the quality views of both dimensions and the histogram, and with
// stale their names marked " (stale)" too (what a later run removes).
std::vector<std::string> our_view_names(bool stale = true);
inline const std::string kStaleSuffix = " (stale)";

}  // namespace cvtmesh
