#include "core/cvt/lloyd3.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/cvt/anderson.h"
#include "core/cvt/cell_mesh.h"
#include "core/cvt/voronoi_cell3.h"
#include "core/delaunay/delaunay3.h"
#include "core/delaunay/relocate_vertices3.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/locate_point.h"
#include "core/mesh/sort_tets.h"
#include "core/mesh/vertex_star.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// rho = 1/H^5 at every vertex of the mesh (P1 density for the cells); H at every vertex too.
void vertex_density(const TetMesh& m, const SizingField3& sizing, std::vector<int>& hints,
                    std::vector<double>& H, std::vector<double>& rho) {
  const int nv = m.nb_vertices();
  hints.resize(nv, -1);
  H.resize(nv);
  rho.resize(nv);
#pragma omp parallel for schedule(static, 512) if (sizing.thread_safe())
  for (int v = 0; v < nv; ++v) {
    double g[3];
    // No hint yet (first call): start from where the previous vertex of this chunk was found —
    // vertices are in space order, so the walk is short (same chunks for any thread count).
    if (hints[v] < 0 && v % 512 != 0) hints[v] = hints[v - 1];
    H[v] = sizing.eval(m.point(v), g, &hints[v]);
    rho[v] = 1.0 / std::pow(H[v], 5);
  }
}

}  // namespace

CellCentroids voronoi_centroids_3d(const TetMesh& mesh, const SizingField3& sizing,
                                   std::vector<int>* hints) {
  CellCentroids c;
  const int nv = mesh.nb_vertices();
  c.centroid.assign(3 * static_cast<std::size_t>(nv), 0);
  c.mass.assign(nv, 0);
  std::vector<int> local_hints;
  if (!hints) hints = &local_hints;
  std::vector<double> H, rho;
  vertex_density(mesh, sizing, *hints, H, rho);
  const CellMesh cm = prepare_cell_mesh(mesh, &rho);
  CellWorkspace ws;
  for (int v = 0; v < nv; ++v) {
    const double* z = mesh.point(v);
    if (cm.star.nb_tets_of(v) == 0) {
      for (int d = 0; d < 3; ++d) c.centroid[3 * v + d] = z[d];
      continue;
    }
    CellIntegrals ci;
    if (!dual_voronoi_cell(mesh, cm, v, ci)) ci = restricted_voronoi_cell(mesh, cm, v, ws, &rho);
    const Vec3 x = ci.centroid(z);
    for (int d = 0; d < 3; ++d) c.centroid[3 * v + d] = x[d];
    c.mass[v] = ci.mass;
    c.energy += ci.energy;
  }
  return c;
}

namespace {

class Lloyd3Problem {
 public:
  Lloyd3Problem(TetMesh& mesh, const Lloyd3Options& o)
      : m_(mesh), o_(o), delaunay_(Delaunay3::create(o.backend)) {
    if (o_.sizing)
      sizing_ = o_.sizing;
    else
      sizing_ = std::shared_ptr<const SizingField3>(make_mesh_sizing3(mesh).release());
    hints_.assign(m_.nb_vertices(), -1);
    mixer_ = AndersonMixer(o_.anderson_depth);
    constrained_set_ = constrained_faces(m_);
  }

  LloydStep step() {
    LloydStep s;
    const auto t0 = Clock::now();
    evaluate(s);
    s.seconds_cells = seconds_since(t0);
    std::vector<double> target = o_.lbfgs_memory > 0 ? lbfgs_targets(s) : lloyd_targets(s);
    s.seconds_move = seconds_since(t0) - s.seconds_cells;
    move_to(target, s);
    return s;
  }

  int nb_steiner() const { return nb_steiner_; }

  // The last iteration may have left a few faces non-Delaunay or vertices short of their targets
  // (see Lloyd3Options::max_flip_leftover): rebuild the constrained Delaunay mesh of the points.
  void finish() {
    if (mesh_is_cdt_) {
      if (!last_check_full_) verify_after_step(true);
      return;
    }
    const Delaunay3Stats ds = delaunay_->retetrahedralize(m_);
    nb_steiner_ += ds.nb_steiner;
    verify_after_step(true);
    mesh_is_cdt_ = true;
  }

 private:
  // The cells of the current configuration (in cm_ / e_): energy, centroids and masses of the free
  // vertices, D. The cells are independent: computed in parallel into per-vertex slots, then
  // reduced in vertex order (the result does not depend on the number of threads).
  void evaluate(LloydStep& s) {
    const int nv = m_.nb_vertices();
    vertex_density(m_, *sizing_, hints_, H_, rho_);
    // Tets in space order: the per-tet and per-star passes below then hit the cache (flips
    // scatter new tets over free slots; every few iterations is enough; sorted on entry).
    if (++iteration_ % 4 == 0) sort_tets_spatially(m_);
    prepare_cell_mesh(m_, &rho_, delaunay_known_, cm_);
    const VertexStar& star = cm_.star;
    std::vector<CellIntegrals> cells(nv);
    std::vector<char> wanted(nv, 0), clipped(nv, 1);
    for (int v = 0; v < nv; ++v) {
      const bool has_star = star.offset[v] < star.offset[v + 1];
      wanted[v] = has_star && (m_.vclass[v].dim == 3 || o_.compute_energy);
    }
#pragma omp parallel
    {
      CellWorkspace local_ws;
#pragma omp for schedule(dynamic, 64)
      for (int v = 0; v < nv; ++v) {
        if (!wanted[v]) continue;
        if (dual_voronoi_cell(m_, cm_, v, cells[v]))
          clipped[v] = 0;
        else
          cells[v] = restricted_voronoi_cell(m_, cm_, v, local_ws, &rho_);
      }
    }
    for (int v = 0; v < nv; ++v)
      if (wanted[v]) (clipped[v] ? s.nb_clipped_cells : s.nb_dual_cells)++;
    e_ = Evaluation{};
    double dsum = 0;
    for (int v = 0; v < nv; ++v) {
      if (!wanted[v]) continue;
      const CellIntegrals& ci = cells[v];
      s.energy += ci.energy;
      if (m_.vclass[v].dim != 3) continue;
      const double* z = m_.point(v);
      ++s.nb_free;
      Vec3 c = ci.centroid(z);
      double mass = ci.mass;
      if (!(mass > 0) || !std::isfinite(c[0] + c[1] + c[2])) c = vec3(z), mass = 0;
      // D uses the full move to the centroid (the paper's P_i - P*_i).
      dsum += dist2(z, c.data()) / (H_[v] * H_[v]);
      e_.free_ids.push_back(v);
      e_.z.insert(e_.z.end(), z, z + 3);
      e_.c.insert(e_.c.end(), c.begin(), c.end());
      e_.mass.push_back(mass);
    }
    e_.energy = s.energy;
    s.D = s.nb_free ? dsum / s.nb_free : 0.0;
  }

  // The next positions of every vertex (3*#V) for the relaxed, possibly Anderson-mixed, Lloyd step.
  std::vector<double> lloyd_targets(LloydStep& s) {
    const std::vector<int>& free_ids = e_.free_ids;
    std::vector<double> target(m_.xyz);
    const bool accelerated = o_.anderson_depth > 0;
    if (accelerated && have_accepted_ && !last_was_fallback_ && free_ids == accepted_free_ &&
        s.energy > accepted_energy_ * (1 + 1e-12)) {
      // The accelerated step raised the energy: go back to the last accepted configuration and
      // take the plain (relaxed) Lloyd step from there instead. The energy stays monotone.
      s.restarted = true;
      last_was_fallback_ = true;
      mixer_.reset();
      target = accepted_xyz_;
      for (std::size_t i = 0; i < accepted_free_.size(); ++i)
        for (int d = 0; d < 3; ++d) target[3 * accepted_free_[i] + d] = accepted_plain_[3 * i + d];
      // The mesh of accepted_xyz_ is gone (the move safeguards ran when the plain targets were
      // computed, on that mesh): the current, valid mesh moves to the targets.
      return target;
    }
    // Plain relaxed Lloyd targets (kept for a restart), then the accelerated ones.
    const std::vector<double>& z = e_.z;
    std::vector<double> g(z.size());
    for (std::size_t k = 0; k < g.size(); ++k) g[k] = z[k] + o_.relaxation * (e_.c[k] - z[k]);
    std::vector<double> plain(z.size());
    s.nb_limited += safe_targets(g, plain);
    std::vector<double> next = plain;
    if (accelerated) {
      if (free_ids != accepted_free_) mixer_.reset();
      safe_targets(mixer_.next(z, g), next);
    }
    have_accepted_ = true;
    last_was_fallback_ = false;
    accepted_energy_ = s.energy;
    accepted_xyz_ = m_.xyz;
    accepted_free_ = free_ids;
    accepted_plain_ = std::move(plain);
    for (std::size_t i = 0; i < free_ids.size(); ++i)
      for (int d = 0; d < 3; ++d) target[3 * free_ids[i] + d] = next[3 * i + d];
    return target;
  }

  // L-BFGS on F (Liu et al. 2009; see Lloyd3Options::lbfgs_memory). Each call evaluates one
  // configuration: the first, or the trial point of a line search from the last accepted point
  // x_k. Trial accepted (Armijo on the actual moves) -> memory update and a new direction from
  // it; rejected -> a shorter step from x_k, and after a few the plain Lloyd step from x_k.
  std::vector<double> lbfgs_targets(LloydStep& s) {
    const std::size_t n = e_.z.size();
    std::vector<double> g(n);
    for (std::size_t k = 0; k < n; ++k) g[k] = 2 * e_.mass[k / 3] * (e_.z[k] - e_.c[k]);
    if (e_.free_ids != lb_.free_ids) {  // first call, or a rebuild changed the vertex set
      lb_ = LbfgsState{};
      lb_.free_ids = e_.free_ids;
    } else if (lb_.have_point) {
      // The evaluated configuration is the trial x_k + s.
      std::vector<double> sv(n);
      double gs = 0;
      for (std::size_t k = 0; k < n; ++k) sv[k] = e_.z[k] - lb_.z[k], gs += lb_.g[k] * sv[k];
      const bool armijo = gs < 0 && e_.energy <= lb_.energy + 1e-4 * gs;
      if (!armijo && !lb_.forced) {
        s.restarted = true;  // this trial is rejected
        if (++lb_.trials < 3) {
          // Backtrack: the minimiser of the quadratic through F(x_k), its slope and F(trial),
          // within [0.1, 0.5] of the step.
          const double a = lb_.step;
          const double denom = 2 * (e_.energy - lb_.energy - gs);
          double an = denom > 0 ? -gs * a / denom : 0.5 * a;
          an = std::clamp(an, 0.1 * a, 0.5 * a);
          lb_.step = an;
          return lbfgs_point(lb_.dir, an, s);
        }
        // No acceptable step along this direction: the plain Lloyd step from x_k.
        lb_.clear_memory();
        lb_.forced = true;
        std::vector<double> lloyd(n);
        for (std::size_t k = 0; k < n; ++k) lloyd[k] = lb_.c[k] - lb_.z[k];
        return lbfgs_point(lloyd, 1.0, s);
      }
      // Accepted: memory update with the actual step and the gradient change.
      std::vector<double> yv(n);
      double sy = 0, ss = 0, yy = 0;
      for (std::size_t k = 0; k < n; ++k) {
        yv[k] = g[k] - lb_.g[k];
        sy += sv[k] * yv[k], ss += sv[k] * sv[k], yy += yv[k] * yv[k];
      }
      if (sy > 1e-12 * std::sqrt(ss * yy)) {
        lb_.s.push_back(std::move(sv));
        lb_.y.push_back(std::move(yv));
        lb_.rho.push_back(1 / sy);
        if (static_cast<int>(lb_.s.size()) > o_.lbfgs_memory) {
          lb_.s.erase(lb_.s.begin());
          lb_.y.erase(lb_.y.begin());
          lb_.rho.erase(lb_.rho.begin());
        }
      }
    }
    // The evaluated configuration is the new x_k.
    lb_.have_point = true;
    lb_.forced = false;
    lb_.trials = 0;
    lb_.energy = e_.energy;
    lb_.z = e_.z;
    lb_.c = e_.c;
    lb_.g = g;
    // Two-loop recursion: dir = -H g, H0 = diag(relaxation / (2 m_i)) (the relaxed Lloyd step).
    std::vector<double> q = g;
    const int m = static_cast<int>(lb_.s.size());
    std::vector<double> alpha(m);
    auto dot = [n](const std::vector<double>& a, const std::vector<double>& b) {
      double r = 0;
      for (std::size_t k = 0; k < n; ++k) r += a[k] * b[k];
      return r;
    };
    for (int i = m - 1; i >= 0; --i) {
      alpha[i] = lb_.rho[i] * dot(lb_.s[i], q);
      for (std::size_t k = 0; k < n; ++k) q[k] -= alpha[i] * lb_.y[i][k];
    }
    for (std::size_t k = 0; k < n; ++k) {
      const double mass = e_.mass[k / 3];
      q[k] = mass > 0 ? o_.relaxation * q[k] / (2 * mass) : 0;
    }
    for (int i = 0; i < m; ++i) {
      const double beta = lb_.rho[i] * dot(lb_.y[i], q);
      for (std::size_t k = 0; k < n; ++k) q[k] += lb_.s[i][k] * (alpha[i] - beta);
    }
    lb_.dir.assign(n, 0);
    for (std::size_t k = 0; k < n; ++k) lb_.dir[k] = -q[k];
    if (!(dot(g, lb_.dir) < 0)) {  // not a descent direction: Lloyd's
      lb_.clear_memory();
      for (std::size_t k = 0; k < n; ++k) lb_.dir[k] = e_.c[k] - e_.z[k];
    }
    // With an empty memory the direction is Lloyd's step: taken whole, as plain Lloyd would (the
    // density is interpolated on the mesh, so even that step can raise F slightly; shorter steps
    // along it would only cost evaluations).
    lb_.forced = lb_.s.empty();
    lb_.step = 1;
    return lbfgs_point(lb_.dir, 1.0, s);
  }

  // Targets x_k + a * dir (every free vertex, through the move safeguard of the current mesh).
  std::vector<double> lbfgs_point(const std::vector<double>& dir, double a, LloydStep& s) {
    const std::size_t n = dir.size();
    std::vector<double> goal(n), safe(n);
    for (std::size_t k = 0; k < n; ++k) goal[k] = lb_.z[k] + a * dir[k];
    s.nb_limited += safe_targets(goal, safe);
    std::vector<double> target(m_.xyz);
    for (std::size_t i = 0; i < lb_.free_ids.size(); ++i)
      for (int d = 0; d < 3; ++d) target[3 * lb_.free_ids[i] + d] = safe[3 * i + d];
    return target;
  }

  // safe_target for every free vertex of the evaluation (goal/out: 3 per free vertex); returns how
  // many moves were shortened.
  int safe_targets(const std::vector<double>& goal, std::vector<double>& out) const {
    const int nf = static_cast<int>(e_.free_ids.size());
    out.resize(goal.size());
    int nb_limited = 0;
#pragma omp parallel for schedule(static, 256) reduction(+ : nb_limited)
    for (int i = 0; i < nf; ++i)
      if (!safe_target(e_.free_ids[i], &goal[3 * i], cm_.star, cm_.constrained, &out[3 * i]))
        ++nb_limited;
    return nb_limited;
  }

  // Moves the vertices to `target` and re-triangulates (flips, or a rebuild), then checks.
  void move_to(std::vector<double>& target, LloydStep& s) {
    const int nv = m_.nb_vertices();
    const auto t1 = Clock::now();
    bool restored = false;
    bool delaunay = false;
    if (o_.local_flips) {
      const RelocateStats rs = relocate_vertices(m_, constrained_set_, target);
      s.nb_flips = rs.nb_flips;
      s.nb_stuck_faces = rs.nb_stuck;
      s.nb_short_moves = rs.nb_pending;
      delaunay =
          rs.nb_stuck == 0;  // short moves leave a Delaunay mesh of the points where they are
      // Faces the flips cannot make Delaunay are next to the boundary where the constrained
      // Delaunay mesh does not exist without Steiner points (TetGen's rebuild leaves such faces
      // too): they do not call for a rebuild. Vertices short of their targets do, beyond a few.
      restored = rs.ok || rs.nb_pending <= o_.max_flip_leftover * nv;
    }
    // After successful flips every unconstrained face is locally Delaunay; TetGen's rebuild
    // leaves a few non-Delaunay faces near the boundary.
    delaunay_known_ = delaunay;
    mesh_is_cdt_ = delaunay || !restored;
    if (!restored) {
      m_.xyz = target;
      const Delaunay3Stats ds = delaunay_->retetrahedralize(m_);
      nb_steiner_ += ds.nb_steiner;
      s.rebuilt = true;
    }
    s.seconds_delaunay = seconds_since(t1);
    const auto t2 = Clock::now();
    // The whole structure (check_mesh) every 4th iteration, after a rebuild and at the end; the
    // orientation of every tet after every move (see verify_after_step).
    verify_after_step(s.rebuilt || iteration_ % 4 == 0);
    s.seconds_check = seconds_since(t2);
  }

  // The move of v towards `goal`, shortened (halved) until the point lies in v's region and is
  // reachable from v's star without crossing the boundary or an interface. Writes the position
  // (v's own if every try failed); returns false if the move was shortened.
  bool safe_target(int v, const double* goal, const VertexStar& star,
                   const std::vector<char>& constrained, double* out) const {
    const double* z = m_.point(v);
    double t = 1.0;
    for (int h = 0; h <= o_.max_halvings; ++h, t *= 0.5) {
      double x[3];
      for (int d = 0; d < 3; ++d) x[d] = z[d] + t * (goal[d] - z[d]);
      const LocateResult r = locate_point(m_, x, star.tets[star.offset[v]], &constrained, 100000);
      if (r.status == LocateStatus::kInside) {
        for (int d = 0; d < 3; ++d) out[d] = x[d];
        return h == 0;
      }
    }
    for (int d = 0; d < 3; ++d) out[d] = z[d];
    return false;
  }

  // full: check_mesh (orientation, adjacency, closed boundary, constrained triangles present,
  // interfaces). Otherwise every live tet's orientation (exact orient3d, in parallel): the moves
  // and flips change connectivity only through apply_swap, whose structure the full check
  // verifies every few iterations and at the end.
  void verify_after_step(bool full) {
    last_check_full_ = full;
    if (full) {
      const MeshCheck c = check_mesh(m_);
      if (!c.ok)
        throw InvariantError("Lloyd iteration produced an invalid mesh: " +
                             (c.problems.empty() ? std::string("?") : c.problems.front()));
    } else {
      if (const int bad = last_non_positive_tet(m_); bad >= 0)
        throw InvariantError("Lloyd iteration produced an invalid mesh: tet " +
                             std::to_string(bad) + " is inverted or flat");
    }
    // Every vertex that had tets must still have some (no point lost in a hole).
    std::vector<char> used(m_.nb_vertices(), 0);
    for (int t = 0; t < m_.nb_tets(); ++t)
      if (m_.tets[4 * t] >= 0)
        for (int k = 0; k < 4; ++k) used[m_.tets[4 * t + k]] = 1;
    for (int v = 0; v < m_.nb_vertices(); ++v)
      if (m_.vclass[v].dim == 3 && !used[v])
        throw InvariantError("Lloyd iteration left interior vertex " + std::to_string(v) +
                             " outside every tet");
  }

  struct Evaluation {
    double energy = 0;
    std::vector<int> free_ids;
    std::vector<double> z, c, mass;  // positions, cell centroids (3 per free vertex), masses
  };
  struct LbfgsState {
    std::vector<int> free_ids;
    bool have_point = false;  // x_k below is set
    bool forced = false;      // the pending trial is the plain Lloyd step: accepted as it comes
    int trials = 0;           // rejected trials along the current direction
    double energy = 0, step = 1;
    std::vector<double> z, c, g, dir;  // x_k: free positions, centroids, gradient; direction
    std::vector<std::vector<double>> s, y;
    std::vector<double> rho;
    void clear_memory() {
      s.clear();
      y.clear();
      rho.clear();
    }
  };

  TetMesh& m_;
  Lloyd3Options o_;
  CellMesh cm_;
  Evaluation e_;
  LbfgsState lb_;
  std::unique_ptr<Delaunay3> delaunay_;
  ConstrainedFaces constrained_set_;  // the constrained triangles never change
  bool delaunay_known_ = false;       // every unconstrained face is locally Delaunay
  bool mesh_is_cdt_ = true;           // the mesh is the constrained Delaunay one of its points
  int iteration_ = 0;
  bool last_check_full_ = true;
  std::shared_ptr<const SizingField3> sizing_;
  std::vector<int> hints_;
  std::vector<double> H_, rho_;
  int nb_steiner_ = 0;
  AndersonMixer mixer_{0};
  bool have_accepted_ = false;
  // The plain step taken after a restart is accepted whatever its energy (the density is P1 on
  // the current mesh, so the energy is not exactly monotone even for plain Lloyd): no endless
  // restarts.
  bool last_was_fallback_ = false;
  double accepted_energy_ = 0;
  std::vector<double> accepted_xyz_, accepted_plain_;
  std::vector<int> accepted_free_;
};

}  // namespace

LloydResult lloyd_optimize_3d(TetMesh& mesh, const Lloyd3Options& options,
                              const std::function<void(const LloydStep&)>& progress) {
  // Free vertices in space order (fixed ones keep their ids) and the tets too: a tet's points, and
  // neighbouring tets, are then close in memory. Both are permutations (the same mesh), done
  // first so that the validity check below already runs on the ordered mesh; they only need the
  // vertex ids in range.
  const int nv = mesh.nb_vertices();
  for (int v : mesh.tets)
    if (v >= nv)
      throw InvariantError("lloyd_optimize_3d: invalid input mesh: vertex id out of range");
  for (int v : mesh.tris)
    if (v < 0 || v >= nv)
      throw InvariantError("lloyd_optimize_3d: invalid input mesh: vertex id out of range");
  sort_free_vertices_spatially(mesh);
  sort_tets_spatially(mesh);
  const MeshCheck c = check_mesh(mesh);
  if (!c.ok) throw InvariantError("lloyd_optimize_3d: invalid input mesh: " + c.problems.front());
  Lloyd3Problem problem(mesh, options);
  LloydResult r = lloyd_iterate(problem, options.lloyd, progress);
  problem.finish();
  return r;
}

}  // namespace cvtmesh
