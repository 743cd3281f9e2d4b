#include "core/cvt/lloyd_optimize_2d.h"

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "core/cvt/anderson.h"
#include "core/cvt/lbfgs.h"
#include "core/cvt/voronoi_centroids2d.h"
#include "core/delaunay/cdt2d_locate.h"
#include "core/delaunay/cdt2d_remesh.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/edge_index.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

std::string first_problem(const MeshCheck& c) {
  return c.problems.empty() ? "" : c.problems[0];
}

// Uniform double in [0, 1) from the generator's raw bits (same on every platform).
double uniform01(std::mt19937& g) {
  const std::uint64_t hi = g() >> 5, lo = g() >> 6;
  return (static_cast<double>(hi) * 67108864.0 + static_cast<double>(lo)) / 9007199254740992.0;
}

// The 2D line search: halvings of the nominal step (at most 10), Armijo on it, H0 = 1 / (2 m);
// when it gives up, the plain Lloyd step and a fresh start.
LbfgsRules lbfgs_rules(const Lloyd2dOptions& o) {
  LbfgsRules r;
  r.memory = o.lbfgs_memory;
  r.max_trials = 10;
  r.backtrack = LbfgsRules::Backtrack::kHalve;
  r.armijo_on_actual_move = false;
  r.lloyd_direction_untested = false;
  r.fallback = LbfgsRules::Fallback::kRestart;
  return r;
}

class Lloyd2dProblem {
 public:
  Lloyd2dProblem(TriMesh2& mesh, const Lloyd2dOptions& o, const SizingField2d& sizing)
      : mesh_(mesh), o_(o), sizing_(sizing), mixer_(o.anderson_depth), lbfgs_(lbfgs_rules(o)) {
    std::vector<char> on_edge(mesh.nb_vertices(), 0);
    for (int v : mesh.edges) on_edge[v] = 1;
    for (int v = 0; v < mesh.nb_vertices(); ++v)
      if (mesh.vclass[v].dim == 2 && !on_edge[v]) free_.push_back(v);
    size_hint_.assign(free_.size(), -1);
  }

  // The CVT energy F of the current mesh (all cells).
  double energy() const {
    double e = 0;
    for (const VoronoiCell2d& c : voronoi_centroids2d(mesh_, sizing_, true, &delaunay_))
      e += c.energy;
    return e;
  }

  // Moves every free vertex by a random vector uniform in the disk of radius amount * H(z)
  // (halved by safe_target until it stays inside its surface), then rebuilds the mesh.
  void kick(double amount, std::mt19937& rng, int hop) {
    hop_ = hop;
    have_cells_ = false;
    prepare_safeguard();
    const std::size_t n = free_.size();
    std::vector<double> next(2 * n);
    for (std::size_t k = 0; k < n; ++k) {
      const double* z = mesh_.point(free_[k]);
      const double r = amount * sizing_.size(z, size_hint_[k]) * std::sqrt(uniform01(rng));
      const double a = 2 * M_PI * uniform01(rng);
      const double goal[2] = {z[0] + r * std::cos(a), z[1] + r * std::sin(a)};
      safe_target(free_[k], goal, &next[2 * k]);
    }
    for (std::size_t k = 0; k < n; ++k) {
      double* p = mesh_.point(free_[k]);
      p[0] = next[2 * k], p[1] = next[2 * k + 1];
    }
    cdt2d_remesh(mesh_, &delaunay_);
  }

  LloydStep step() {
    if (o_.lbfgs_memory > 0) return step_lbfgs();
    LloydStep s;
    s.hop = hop_;
    s.nb_free = static_cast<int>(free_.size());
    const std::vector<VoronoiCell2d> cells = voronoi_centroids2d(mesh_, sizing_, true, &delaunay_);
    for (const VoronoiCell2d& c : cells) s.energy += c.energy;
    const std::size_t n = free_.size();
    std::vector<double> z(2 * n), c(2 * n);
    double D = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const int v = free_[k];
      const double* p = mesh_.point(v);
      const double h = sizing_.size(p, size_hint_[k]);
      for (int d = 0; d < 2; ++d) z[2 * k + d] = p[d], c[2 * k + d] = cells[v].centroid[d];
      const double dx = c[2 * k] - z[2 * k], dy = c[2 * k + 1] - z[2 * k + 1];
      D += (dx * dx + dy * dy) / (h * h);  // the paper's D: the full move to the centroid
    }
    s.D = n ? D / static_cast<double>(n) : 0;

    const bool accelerated = o_.anderson_depth > 0;
    std::vector<double> next;
    if (accelerated && have_accepted_ && !just_restarted_ &&
        s.energy > accepted_energy_ * (1 + 1e-12)) {
      // The accelerated step raised the energy: take the plain (relaxed) Lloyd step from the
      // last accepted configuration instead (its targets were checked on its mesh), so the
      // accepted energies never increase.
      s.restarted = true;
      just_restarted_ = true;  // the plain step is accepted as it comes (no restart loop)
      mixer_.reset();
      next = accepted_plain_;
    } else {
      just_restarted_ = false;
      prepare_safeguard();
      std::vector<double> g(2 * n);
      for (std::size_t k = 0; k < 2 * n; ++k) g[k] = z[k] + o_.relaxation * (c[k] - z[k]);
      std::vector<double> plain(2 * n);
      for (std::size_t k = 0; k < n; ++k)
        if (!safe_target(free_[k], &g[2 * k], &plain[2 * k])) ++s.nb_limited;
      next = plain;
      if (accelerated) {
        const std::vector<double> mixed = mixer_.next(z, g);
        for (std::size_t k = 0; k < n; ++k) safe_target(free_[k], &mixed[2 * k], &next[2 * k]);
        have_accepted_ = true;
        accepted_energy_ = s.energy;
        accepted_plain_ = std::move(plain);
      }
    }
    for (std::size_t k = 0; k < n; ++k) {
      double* p = mesh_.point(free_[k]);
      p[0] = next[2 * k], p[1] = next[2 * k + 1];
    }
    cdt2d_remesh(mesh_, &delaunay_);
    return s;
  }

  // One L-BFGS iteration on F (lbfgs.h; Liu et al. 2009): gradient dF/dz_i = 2 m_i (z_i - c_i),
  // initial inverse Hessian diag(1 / (2 m_i)) (so the first direction is Lloyd's step), a
  // backtracking line search (Armijo on the nominal step, at most 10 halvings) over steps whose
  // every target stays strictly inside its surface, the mesh rebuilt (constrained Delaunay) at
  // each trial. If no step is accepted, the plain Lloyd step is taken and the memory cleared
  // (LloydStep::restarted).
  LloydStep step_lbfgs() {
    LloydStep s;
    s.hop = hop_;
    const std::size_t n = free_.size();
    s.nb_free = static_cast<int>(n);
    if (!have_cells_) {  // a first point (the start, or after a plain Lloyd step)
      cells_ = voronoi_centroids2d(mesh_, sizing_, true, &delaunay_), have_cells_ = true;
      lbfgs_.tell(lbfgs_point(cells_));
    }
    s.energy = lbfgs_.current().energy;
    double D = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const VoronoiCell2d& c = cells_[free_[k]];
      const double* p = mesh_.point(free_[k]);
      const double h = sizing_.size(p, size_hint_[k]);
      const double dx = c.centroid[0] - p[0], dy = c.centroid[1] - p[1];
      D += (dx * dx + dy * dy) / (h * h);
    }
    s.D = n ? D / static_cast<double>(n) : 0;
    if (s.D < o_.lloyd.tolerance) return s;  // converged: lloyd_iterate stops, nothing to move

    prepare_safeguard();
    const TriMesh2 backup = mesh_;
    for (;;) {
      const std::vector<double> target = lbfgs_.trial_point();
      bool inside = true;
      for (std::size_t k = 0; k < n && inside; ++k)
        inside = strictly_inside(free_[k], &target[2 * k]);
      LbfgsVerdict verdict;
      if (!inside) {
        verdict = lbfgs_.reject_unevaluated();
      } else {
        for (std::size_t k = 0; k < n; ++k) {
          double* p = mesh_.point(free_[k]);
          p[0] = target[2 * k], p[1] = target[2 * k + 1];
        }
        cdt2d_remesh(mesh_, &delaunay_);
        std::vector<VoronoiCell2d> trial = voronoi_centroids2d(mesh_, sizing_, true, &delaunay_);
        verdict = lbfgs_.tell(lbfgs_point(trial));
        if (verdict == LbfgsVerdict::kAccepted)
          cells_ = std::move(trial);
        else
          mesh_ = backup, delaunay_ = Cdt2dResult();
      }
      if (verdict == LbfgsVerdict::kAccepted) break;
      if (verdict == LbfgsVerdict::kExhausted) return plain_lloyd_step(s);
    }
    // Counted for every accepted step (the line search's loop used to halve its step once more
    // after accepting it, then counted steps below 1).
    ++s.nb_limited;
    return s;
  }

 private:
  // The L-BFGS point of the current mesh, whose cells are `cells`: F over all cells, the free
  // positions, dF/dz = 2 m (z - c), H0 = diag(1 / (2 m)) and the Lloyd step -H0 g.
  LbfgsPoint lbfgs_point(const std::vector<VoronoiCell2d>& cells) const {
    const std::size_t n = free_.size();
    LbfgsPoint pt;
    for (const VoronoiCell2d& c : cells) pt.energy += c.energy;
    pt.x.resize(2 * n), pt.gradient.resize(2 * n), pt.lloyd_step.resize(2 * n);
    std::vector<double> h0(2 * n);
    for (std::size_t k = 0; k < n; ++k) {
      const VoronoiCell2d& c = cells[free_[k]];
      const double* p = mesh_.point(free_[k]);
      for (int d = 0; d < 2; ++d) {
        pt.x[2 * k + d] = p[d];
        pt.gradient[2 * k + d] = 2 * c.mass * (p[d] - c.centroid[d]);
        h0[2 * k + d] = c.mass > 0 ? 1 / (2 * c.mass) : 0;
        pt.lloyd_step[2 * k + d] = -h0[2 * k + d] * pt.gradient[2 * k + d];
      }
    }
    pt.initial_inverse_hessian = [h0 = std::move(h0)](std::vector<double>& q) {
      for (std::size_t k = 0; k < q.size(); ++k) q[k] *= h0[k];
    };
    return pt;
  }

  // The L-BFGS line search gave up: the plain Lloyd step (lowers F for the current partition),
  // from which the minimiser starts afresh.
  LloydStep plain_lloyd_step(LloydStep& s) {
    s.restarted = true;
    const std::size_t n = free_.size();
    std::vector<double> next(2 * n);
    for (std::size_t k = 0; k < n; ++k) {
      const double* c = cells_[free_[k]].centroid;
      if (!safe_target(free_[k], c, &next[2 * k])) ++s.nb_limited;
    }
    for (std::size_t k = 0; k < n; ++k) {
      double* p = mesh_.point(free_[k]);
      p[0] = next[2 * k], p[1] = next[2 * k + 1];
    }
    cdt2d_remesh(mesh_, &delaunay_);
    have_cells_ = false;
    return s;
  }

  // Constrained slots and a triangle at each vertex of the current mesh, for safe_target.
  void prepare_safeguard() {
    const int nt = mesh_.nb_tris();
    const EdgeIndex ce(mesh_.edges, mesh_.nb_vertices());
    stop_.assign(3 * static_cast<std::size_t>(nt), 0);
    vtri_.assign(mesh_.nb_vertices(), -1);
    for (int t = 0; t < nt; ++t) {
      const int* tv = &mesh_.tris[3 * t];
      if (tv[0] < 0) continue;
      for (int k = 0; k < 3; ++k) {
        vtri_[tv[k]] = t;
        stop_[3 * t + k] = ce.contains(tv[(k + 1) % 3], tv[(k + 2) % 3]);
      }
    }
  }

  // p is strictly inside v's surface: reached from v's triangles without crossing a constrained
  // edge, off every constrained edge and other vertex (prepare_safeguard first).
  bool strictly_inside(int v, const double* p) const {
    const Locate2dResult r = locate2d(mesh_, p, vtri_[v], stop_);
    return r.tri >= 0 && (r.on_vertex < 0 || r.on_vertex == v) &&
           (r.on_edge < 0 || !stop_[3 * r.tri + r.on_edge]);
  }

  // The move of v towards goal, halved until the point is strictly inside v's surface (reached
  // from v's triangles without crossing a constrained edge, off every constrained edge and other
  // vertex). Writes the position (v's own if every try failed); false if shortened.
  bool safe_target(int v, const double* goal, double* out) const {
    const double* z = mesh_.point(v);
    double t = 1;
    for (int h = 0; h <= o_.max_halvings; ++h, t *= 0.5) {
      const double p[2] = {z[0] + t * (goal[0] - z[0]), z[1] + t * (goal[1] - z[1])};
      if (strictly_inside(v, p)) {
        out[0] = p[0], out[1] = p[1];
        return h == 0;
      }
    }
    out[0] = z[0], out[1] = z[1];
    return false;
  }

  TriMesh2& mesh_;
  // The unconstrained Delaunay triangulation of mesh_'s vertices, from the last rebuild
  // (cdt2d_remesh), for the next cells; empty: computed by voronoi_centroids2d.
  Cdt2dResult delaunay_;
  Lloyd2dOptions o_;
  const SizingField2d& sizing_;
  std::vector<int> free_;
  // Per free vertex, the background triangle of its last size lookup (SizingField2d::size's
  // hint): a vertex moves little from one iteration to the next, so its walk is short.
  std::vector<int> size_hint_;
  std::vector<char> stop_;
  std::vector<int> vtri_;
  AndersonMixer mixer_;
  bool have_accepted_ = false, just_restarted_ = false;
  double accepted_energy_ = 0;
  std::vector<double> accepted_plain_;
  int hop_ = 0;
  // L-BFGS: centroids at the current mesh (valid if have_cells_, then told to lbfgs_).
  bool have_cells_ = false;
  std::vector<VoronoiCell2d> cells_;
  LbfgsMinimizer lbfgs_;
};

}  // namespace

LloydResult lloyd_optimize_2d(TriMesh2& mesh, const Lloyd2dOptions& options,
                              const std::function<void(const LloydStep&)>& progress,
                              Lloyd2dReport* report) {
  if (mesh.adj.size() != mesh.tris.size()) build_adjacency2(mesh);
  const MeshCheck before = check_mesh(mesh);
  if (!before.ok)
    throw InputError("lloyd_optimize_2d: invalid input mesh: " + first_problem(before));
  const SizingField2d sizing(mesh, options.sizing);  // from the input mesh, for every run
  Lloyd2dReport rep;
  LloydResult r;
  {
    Lloyd2dProblem problem(mesh, options, sizing);
    r = lloyd_iterate(problem, options.lloyd, progress);
    rep.lloyd_energy = rep.energy = problem.energy();
    rep.lloyd_iterations = r.iterations;
  }
  if (options.hops > 0) {
    std::mt19937 rng(options.hop_seed);
    TriMesh2 best = mesh;
    for (int hop = 1; hop <= options.hops; ++hop) {
      TriMesh2 trial = best;
      Lloyd2dProblem problem(trial, options, sizing);
      problem.kick(options.hop_amount, rng, hop);
      const LloydResult hr = lloyd_iterate(problem, options.lloyd, progress);
      const double e = problem.energy();
      r.iterations += hr.iterations;
      r.history.insert(r.history.end(), hr.history.begin(), hr.history.end());
      const bool accept = hr.converged && e < rep.energy;
      rep.hop_energies.push_back(e);
      if (accept) {
        best = std::move(trial);
        rep.energy = e;
        ++rep.hops_accepted;
      }
      ++rep.hops;
    }
    mesh = std::move(best);
  }
  if (report) *report = rep;
  const MeshCheck after = check_mesh(mesh);
  if (!after.ok)
    throw InvariantError("lloyd_optimize_2d: mesh invalid after Lloyd: " + first_problem(after));
  return r;
}

}  // namespace cvtmesh
