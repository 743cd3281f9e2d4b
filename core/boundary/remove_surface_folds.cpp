#include "core/boundary/remove_surface_folds.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/collapse_boundary_edges.h"
#include "core/mesh/build_adjacency.h"
#include "core/mesh/vertex_tets.h"
#include "core/swap/compact_tets.h"

namespace cvtmesh {

FoldRemovalStats remove_surface_folds(TetMesh& mesh, BoundaryModel& model,
                                      const FoldRemovalOptions& o) {
  FoldRemovalStats stats;
  if (!model.geometry) return stats;
  BoundaryCollapseOptions co;
  co.fold_vertices = true;
  co.flat_angle = o.flat_angle;
  co.hausdorff = o.hausdorff;
  co.volume_budget = o.volume_budget;
  // The check reads the spacing only to bound the new edges' length: no bound here (the triangle
  // left is made of the fold's neighbours' edges).
  co.long_fraction = std::numeric_limits<double>::infinity();
  bool changed = false;
  for (int pass = 0; pass < o.passes; ++pass) {
    const BoundaryFans fans = boundary_fans(mesh);
    std::vector<int> folds;
    for (int v = 0; v < mesh.nb_vertices(); ++v)
      if (is_fold_vertex(mesh, model, fans, v)) folds.push_back(v);
    if (pass == 0) stats.nb_folds = static_cast<long>(folds.size());
    if (folds.empty()) break;
    if (mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);
    const VertexTets star = vertex_tets(mesh);
    const std::vector<double> spacing(static_cast<std::size_t>(mesh.nb_vertices()), 1.0);
    std::vector<char> dirty(spacing.size(), 0);
    long removed = 0;
    // Whether x's star is as at the pass's start: no vertex of it in a collapse of this pass.
    auto clean_star = [&](int x) {
      for (const int* t = star.begin_of(x); t != star.end_of(x); ++t)
        for (int k = 0; k < 4; ++k)
          if (dirty[mesh.tets[4 * static_cast<std::size_t>(*t) + k]]) return false;
      return true;
    };
    for (int v : folds) {
      // Not where an earlier collapse of this pass changed the stars or fans (the next pass).
      if (!clean_star(v)) continue;
      std::vector<int> ring;
      for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f)
        for (int k = 0; k < 3; ++k) {
          const int x = mesh.tris[3 * static_cast<std::size_t>(*f) + k];
          if (x != v && std::find(ring.begin(), ring.end(), x) == ring.end()) ring.push_back(x);
        }
      for (int w : ring) {
        CollapsePlan plan;
        if (!clean_star(w) || plan_boundary_collapse(mesh, model, star, fans, spacing, v, w, co,
                                                     plan) != CollapseCheck::kOk)
          continue;
        for (const int* t = star.begin_of(v); t != star.end_of(v); ++t)
          for (int k = 0; k < 4; ++k) dirty[mesh.tets[4 * static_cast<std::size_t>(*t) + k]] = 1;
        apply_boundary_collapse(mesh, model, plan, o.volume_budget);
        ++removed;
        ++stats.nb_removed;
        break;
      }
    }
    if (removed == 0) break;
    compact_boundary_triangles(mesh);
    changed = true;
  }
  if (changed) compact_tets(mesh);  // remaps the adjacency
  return stats;
}

}  // namespace cvtmesh
