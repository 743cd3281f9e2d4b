#include "core/smoothing/smooth2d.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/mesh/check_mesh.h"
#include "core/swap/flip2d_pass.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

std::string first_problem(const MeshCheck& c) {
  return c.problems.empty() ? "" : c.problems[0];
}

// Length of the segment a-b in the metric 1/H, H linear along it between ha and hb.
double metric_length(double len, double ha, double hb) {
  if (std::fabs(hb - ha) <= 1e-9 * (ha + hb)) return 2 * len / (ha + hb);
  return len * std::log(hb / ha) / (hb - ha);
}

class SmoothProblem {
 public:
  SmoothProblem(TriMesh2& mesh, SmoothMove2d move, const Smooth2dOptions& o)
      : mesh_(mesh), move_(move), flips_(o.flips), sizing_(mesh, o.sizing) {
    std::vector<char> on_edge(mesh.nb_vertices(), 0);
    for (int v : mesh.edges) on_edge[v] = 1;
    for (int v = 0; v < mesh.nb_vertices(); ++v)
      if (mesh.vclass[v].dim == 2 && !on_edge[v]) free_.push_back(v);
  }

  LloydStep step() {
    LloydStep s;
    s.nb_free = static_cast<int>(free_.size());
    const int nv = mesh_.nb_vertices(), nt = mesh_.nb_tris();
    // Triangles around each vertex (CSR); the connectivity is fixed during the sweep.
    std::vector<int> start(nv + 1, 0), around;
    for (int t = 0; t < nt; ++t)
      if (mesh_.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k) ++start[mesh_.tris[3 * t + k] + 1];
    for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
    around.resize(start[nv]);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int t = 0; t < nt; ++t)
      if (mesh_.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k) around[fill[mesh_.tris[3 * t + k]]++] = t;

    double D = 0;
    std::vector<int> ring;
    for (int v : free_) {
      ring.clear();
      for (int k = start[v]; k < start[v + 1]; ++k)
        for (int j = 0; j < 3; ++j) {
          const int u = mesh_.tris[3 * around[k] + j];
          if (u != v) ring.push_back(u);
        }
      std::sort(ring.begin(), ring.end());
      ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
      if (ring.empty()) continue;
      double* z = mesh_.point(v);
      const double old[2] = {z[0], z[1]};
      const double hz = sizing_.size(old);
      double p[2] = {0, 0};
      for (int u : ring) {
        const double* q = mesh_.point(u);
        if (move_ == SmoothMove2d::kLaplacian) {
          p[0] += q[0], p[1] += q[1];
          continue;
        }
        // P_u* = P_u + (P - P_u) / l(P_u P): at unit metric length from P_u towards P.
        const double len = std::hypot(old[0] - q[0], old[1] - q[1]);
        const double l = metric_length(len, sizing_.size(q), hz);
        p[0] += q[0] + (old[0] - q[0]) / l;
        p[1] += q[1] + (old[1] - q[1]) / l;
      }
      p[0] /= static_cast<double>(ring.size()), p[1] /= static_cast<double>(ring.size());
      z[0] = p[0], z[1] = p[1];
      bool valid = true;
      for (int k = start[v]; k < start[v + 1] && valid; ++k) {
        const int* tv = &mesh_.tris[3 * around[k]];
        valid = orient2d(mesh_.point(tv[0]), mesh_.point(tv[1]), mesh_.point(tv[2])) > 0;
      }
      if (!valid) {
        z[0] = old[0], z[1] = old[1];
        ++s.nb_limited;
        continue;
      }
      D += ((p[0] - old[0]) * (p[0] - old[0]) + (p[1] - old[1]) * (p[1] - old[1])) / (hz * hz);
    }
    s.D = free_.empty() ? 0 : D / static_cast<double>(free_.size());
    if (flips_) flip2d_pass(mesh_);
    return s;
  }

 private:
  TriMesh2& mesh_;
  SmoothMove2d move_;
  bool flips_;
  SizingField2d sizing_;
  std::vector<int> free_;
};

}  // namespace

LloydResult smooth_optimize_2d(TriMesh2& mesh, SmoothMove2d move, const Smooth2dOptions& options,
                               const std::function<void(const LloydStep&)>& progress) {
  if (mesh.adj.size() != mesh.tris.size()) build_adjacency2(mesh);
  const MeshCheck before = check_mesh(mesh);
  if (!before.ok) throw InputError("smoothing: invalid input mesh: " + first_problem(before));
  SmoothProblem problem(mesh, move, options);
  LloydResult r = lloyd_iterate(problem, options.loop, progress);
  const MeshCheck after = check_mesh(mesh);
  if (!after.ok)
    throw InvariantError("smoothing: mesh invalid after smoothing: " + first_problem(after));
  return r;
}

}  // namespace cvtmesh
