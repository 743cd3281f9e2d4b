#include "core/cvt/lloyd_optimize_2d.h"

#include <string>
#include <unordered_set>
#include <vector>

#include "core/cvt/voronoi_centroids2d.h"
#include "core/delaunay/cdt2d_locate.h"
#include "core/delaunay/cdt2d_remesh.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/face_key.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

std::string first_problem(const MeshCheck& c) {
  return c.problems.empty() ? "" : c.problems[0];
}

class Lloyd2dProblem {
 public:
  Lloyd2dProblem(TriMesh2& mesh, const SizingField2dOptions& sizing)
      : mesh_(mesh), sizing_(mesh, sizing) {
    std::vector<char> on_edge(mesh.nb_vertices(), 0);
    for (int v : mesh.edges) on_edge[v] = 1;
    for (int v = 0; v < mesh.nb_vertices(); ++v)
      if (mesh.vclass[v].dim == 2 && !on_edge[v]) free_.push_back(v);
    if (!sizing_.is_uniform()) density_ = [this](const double* x) { return sizing_.density(x); };
  }

  int nb_free() const { return static_cast<int>(free_.size()); }

  LloydStep step() {
    LloydStep s;
    s.nb_free = nb_free();
    const std::vector<VoronoiCell2d> cells = voronoi_centroids2d(mesh_, density_);
    for (const VoronoiCell2d& c : cells) s.energy += c.energy;

    // Where each free vertex may go: strictly inside its own surface (a walk that never crosses
    // a constrained edge, ending off every constrained edge and vertex).
    const int nt = mesh_.nb_tris();
    std::unordered_set<EdgeKey, EdgeKeyHash> ce;
    for (int e = 0; e < mesh_.nb_edges(); ++e)
      ce.insert(edge_key(mesh_.edges[2 * e], mesh_.edges[2 * e + 1]));
    std::vector<char> stop(3 * static_cast<std::size_t>(nt), 0);
    std::vector<int> vtri(mesh_.nb_vertices(), -1);
    for (int t = 0; t < nt; ++t) {
      const int* tv = &mesh_.tris[3 * t];
      if (tv[0] < 0) continue;
      for (int k = 0; k < 3; ++k) {
        vtri[tv[k]] = t;
        stop[3 * t + k] = ce.count(edge_key(tv[(k + 1) % 3], tv[(k + 2) % 3])) ? 1 : 0;
      }
    }
    auto allowed = [&](int v, const double* p) {
      const Locate2dResult r = locate2d(mesh_, p, vtri[v], stop);
      if (r.tri < 0) return false;
      if (r.on_vertex >= 0 && r.on_vertex != v) return false;
      return r.on_edge < 0 || !stop[3 * r.tri + r.on_edge];
    };

    std::vector<double> target(2 * free_.size());
    double D = 0;
    for (std::size_t k = 0; k < free_.size(); ++k) {
      const int v = free_[k];
      const double* z = mesh_.point(v);
      const double* c = cells[v].centroid;
      const double h = sizing_.size(z);
      const double dx = c[0] - z[0], dy = c[1] - z[1];
      D += (dx * dx + dy * dy) / (h * h);
      double f = 1;
      bool ok = false;
      for (int halving = 0; halving <= 10; ++halving, f *= 0.5) {
        const double p[2] = {z[0] + f * dx, z[1] + f * dy};
        if (allowed(v, p)) {
          ok = true;
          break;
        }
      }
      if (!ok) f = 0;
      if (f < 1) ++s.nb_limited;
      target[2 * k] = z[0] + f * dx;
      target[2 * k + 1] = z[1] + f * dy;
    }
    s.D = free_.empty() ? 0 : D / static_cast<double>(free_.size());
    for (std::size_t k = 0; k < free_.size(); ++k) {
      double* z = mesh_.point(free_[k]);
      z[0] = target[2 * k], z[1] = target[2 * k + 1];
    }
    cdt2d_remesh(mesh_);
    return s;
  }

 private:
  TriMesh2& mesh_;
  SizingField2d sizing_;
  std::function<double(const double*)> density_;
  std::vector<int> free_;
};

}  // namespace

LloydResult lloyd_optimize_2d(TriMesh2& mesh, const Lloyd2dOptions& options,
                              const std::function<void(const LloydStep&)>& progress) {
  if (mesh.adj.size() != mesh.tris.size()) build_adjacency2(mesh);
  const MeshCheck before = check_mesh(mesh);
  if (!before.ok)
    throw InputError("lloyd_optimize_2d: invalid input mesh: " + first_problem(before));
  Lloyd2dProblem problem(mesh, options.sizing);
  LloydResult r = lloyd_iterate(problem, options.lloyd, progress);
  const MeshCheck after = check_mesh(mesh);
  if (!after.ok)
    throw InvariantError("lloyd_optimize_2d: mesh invalid after Lloyd: " + first_problem(after));
  return r;
}

}  // namespace cvtmesh
