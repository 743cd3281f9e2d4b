#include "core/boundary/remove_low_step_caps.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/collapse_boundary_edges.h"
#include "core/mesh/build_adjacency.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/vertex_time_step.h"
#include "core/swap/compact_tets.h"

namespace cvtmesh {

LowCapStats remove_low_step_caps(TetMesh& mesh, BoundaryModel& model, const LowCapOptions& o) {
  LowCapStats stats;
  if (!model.geometry || !(o.target > 0)) return stats;
  VertexTimeSteps steps = vertex_time_steps(mesh);
  std::vector<std::pair<double, int>> low;
  for (int v = 0; v < mesh.nb_vertices(); ++v)
    if (steps.dt(v) < o.target) low.push_back({steps.dt(v), v});
  if (low.empty()) return stats;
  if (mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);
  const VertexTets star = vertex_tets(mesh);
  const BoundaryFans fans = boundary_fans(mesh);
  std::sort(low.begin(), low.end());
  BoundaryCollapseOptions co;
  co.cap_vertices = true;
  co.flat_angle = o.flat_angle;
  co.hausdorff = o.hausdorff;
  co.volume_budget = o.volume_budget;
  // No new edge (the triangle left is made of the cap's edges): the spacing is not read.
  co.long_fraction = std::numeric_limits<double>::infinity();
  const std::vector<double> spacing(static_cast<std::size_t>(mesh.nb_vertices()), 1.0);
  std::vector<char> dirty(spacing.size(), 0);
  for (const auto& [dt, v] : low) {
    if (!is_cap_vertex(mesh, model, star, fans, v)) continue;
    ++stats.nb_caps;
    const int t = *star.begin_of(v);
    const int* x = &mesh.tets[4 * static_cast<std::size_t>(t)];
    // Not next to an earlier removal (its tets and fans changed): caps do not share vertices in
    // practice, and the stars stay those of the start.
    if (dirty[x[0]] || dirty[x[1]] || dirty[x[2]] || dirty[x[3]]) continue;
    // The nodal steps of the other three without the tet.
    double k[4], m;
    tet_vertex_terms(mesh.point(x[0]), mesh.point(x[1]), mesh.point(x[2]), mesh.point(x[3]), k, &m);
    bool lowers = false;
    for (int i = 0; i < 4; ++i) {
      if (x[i] == v) continue;
      VertexTimeSteps one;
      one.kdiag = {steps.kdiag[x[i]] - k[i]};
      one.mass = {steps.mass[x[i]] - m};
      lowers |= std::min(one.dt(0), o.target) < std::min(steps.dt(x[i]), o.target);
    }
    if (lowers) continue;
    for (int i = 0; i < 4; ++i) {
      if (x[i] == v) continue;
      CollapsePlan plan;
      if (plan_boundary_collapse(mesh, model, star, fans, spacing, v, x[i], co, plan) !=
          CollapseCheck::kOk)
        continue;
      for (int j = 0; j < 4; ++j) {
        dirty[x[j]] = 1;
        if (x[j] != v) {
          steps.kdiag[x[j]] -= k[j];
          steps.mass[x[j]] -= m;
        }
      }
      apply_boundary_collapse(mesh, model, plan, o.volume_budget);
      ++stats.nb_removed;
      break;
    }
  }
  if (stats.nb_removed > 0) {
    compact_boundary_triangles(mesh);
    compact_tets(mesh);  // remaps the adjacency
  }
  return stats;
}

}  // namespace cvtmesh
