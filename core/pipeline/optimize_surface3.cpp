#include "core/pipeline/optimize_surface3.h"

#include <algorithm>
#include <array>
#include <string>

#include "core/boundary/boundary_hausdorff.h"
#include "core/boundary/optimize_surface_mesh.h"
#include "core/mesh/check_surface_mesh.h"
#include "core/quality/quality.h"
#include "core/quality/quality_stats.h"
#include "core/quality/worse_than.h"

namespace cvtmesh {
namespace {

// The edges of the file's line elements (type 1, or 8: an order-2 line by its corners).
std::vector<std::array<int, 2>> line_edges(const TetMesh& m) {
  std::vector<std::array<int, 2>> e;
  for (const ElementBlock& b : m.model.extra) {
    const int npe = b.gmsh_type == 1 ? 2 : b.gmsh_type == 8 ? 3 : 0;
    if (!npe) continue;
    for (std::size_t i = 0; i + npe <= b.nodes.size(); i += npe)
      e.push_back({std::min(b.nodes[i], b.nodes[i + 1]), std::max(b.nodes[i], b.nodes[i + 1])});
  }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end()), e.end());
  return e;
}

double worst_triangle_q(const TetMesh& m) {
  return min_quality(m, Measure::kQ);
}

}  // namespace

void optimize_surface3(TetMesh& mesh, const OptimizeOptions& o, const BoundaryModel& model,
                       double operators, double bound, OptimizeResult& r) {
  r.before = quality_stats(mesh, "before");
  r.tri_q_min_before = worst_triangle_q(mesh);
  const TetMesh input = mesh;
  SurfaceMeshOptions so;
  if (o.max_iterations > 0) so.rounds = o.max_iterations;  // resolve(): 100 by default
  // As for a tet mesh, only the default method moves the boundary (here every vertex); the
  // paper's methods and --fix-boundary keep it: flips of coplanar edges only.
  const bool fixed = o.fix_boundary || o.method != "cvdt+swap+smooth";
  so.fix_vertices = fixed;
  so.hausdorff = operators;
  so.kept_edges = line_edges(mesh);
  if (o.progress)
    so.progress = [&o](int round, double q_min, double q_avg) {
      OptimizeProgress p;
      p.phase = "bnd-cvt";
      p.iteration = round;
      p.q_min = q_min;
      p.q_avg = q_avg;
      o.progress(p);
    };
  const SurfaceMeshStats st = optimize_surface_mesh(mesh, model, so);
  r.iterations = st.rounds;
  r.converged = st.converged;
  r.boundary_free = !fixed;
  r.boundary_geometry = model.geometry ? model.geometry->kind() : "discrete";
  r.nb_surface_vertices = model.nb_surface_vertices;
  r.nb_curve_vertices = model.nb_curve_vertices;
  r.nb_fixed_vertices = model.nb_fixed_vertices;
  r.diagonal = model.diagonal;
  r.hausdorff_tolerance = bound;
  // The checks of the result: a valid surface mesh, no fold the input did not have, within the
  // Hausdorff bound, and not worse than the input.
  std::string failure;
  const MeshCheck c = check_surface_mesh(mesh);
  if (!c.ok) failure = "the optimized surface mesh is invalid (" + c.problems.front() + ")";
  if (failure.empty() && folded_triangle_pairs(mesh).size() > folded_triangle_pairs(input).size())
    failure = "the optimized surface mesh has folded triangles";
  if (failure.empty() && model.geometry) {
    r.hausdorff = boundary_hausdorff(mesh, *model.geometry).value();
    if (r.hausdorff > bound)
      failure = "the optimized surface is farther from the input than the Hausdorff bound (" +
                std::to_string(r.hausdorff) + " > " + std::to_string(bound) + ")";
  }
  const QualityStats after = quality_stats(mesh, "");
  if (failure.empty() && o.never_worse) {
    const std::string worse = worse_than(after, r.before);
    if (!worse.empty()) failure = "the surface optimization made the mesh worse (" + worse + ")";
  }
  if (!failure.empty()) {
    mesh = input;
    r.kept_input = true;
    r.boundary_free = false;
    r.hausdorff = 0;
    r.notes.push_back(failure + ": the input is kept unchanged");
  } else {
    long moved = 0;
    for (int v = 0; v < mesh.nb_vertices(); ++v)
      moved += mesh.xyz[3 * v] != input.xyz[3 * v] || mesh.xyz[3 * v + 1] != input.xyz[3 * v + 1] ||
               mesh.xyz[3 * v + 2] != input.xyz[3 * v + 2];
    r.nb_boundary_moved = static_cast<int>(moved);
    r.notes.push_back(
        "a surface mesh in space (no tetrahedra): its triangles optimized on their " +
        std::string(r.boundary_geometry) + " surfaces (" +
        (fixed ? "vertices fixed" +
                     (o.fix_boundary
                          ? std::string()
                          : " by the method '" + o.method + "' (only the default moves them)") +
                     ", only flips of coplanar edges"
               : "constrained CVT, edge flips, max-min smoothing") +
        "; " + std::to_string(st.nb_flips) + " flips, round " + std::to_string(st.best_round) +
        " of " + std::to_string(st.rounds) + " kept)");
  }
  r.tri_q_min_after = worst_triangle_q(mesh);
  r.after = quality_stats(mesh, r.method);
}

}  // namespace cvtmesh
