#include "core/cvt/lloyd3.h"

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
    const int nv = m_.nb_vertices();
    const auto t0 = Clock::now();
    vertex_density(m_, *sizing_, hints_, H_, rho_);
    // Tets in space order: the per-tet and per-star passes below then hit the cache (flips
    // scatter new tets over free slots; every few iterations is enough).
    if (iteration_++ % 4 == 0) sort_tets_spatially(m_);
    const CellMesh cm = prepare_cell_mesh(m_, &rho_, delaunay_known_);
    const VertexStar& star = cm.star;
    const std::vector<char>& constrained = cm.constrained;
    // Cells of the current configuration: energy, centroids of the free vertices, D. The cells are
    // independent: computed in parallel into per-vertex slots, then reduced in vertex order (the
    // result does not depend on the number of threads).
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
        if (dual_voronoi_cell(m_, cm, v, cells[v]))
          clipped[v] = 0;
        else
          cells[v] = restricted_voronoi_cell(m_, cm, v, local_ws, &rho_);
      }
    }
    for (int v = 0; v < nv; ++v)
      if (wanted[v]) (clipped[v] ? s.nb_clipped_cells : s.nb_dual_cells)++;
    s.seconds_cells = seconds_since(t0);
    std::vector<int> free_ids;
    std::vector<double> z_free, c_free;
    double dsum = 0;
    for (int v = 0; v < nv; ++v) {
      if (!wanted[v]) continue;
      const CellIntegrals& ci = cells[v];
      s.energy += ci.energy;
      if (m_.vclass[v].dim != 3) continue;
      const double* z = m_.point(v);
      ++s.nb_free;
      Vec3 c = ci.centroid(z);
      if (!(ci.mass > 0) || !std::isfinite(c[0] + c[1] + c[2])) c = vec3(z);
      // D uses the full move to the centroid (the paper's P_i - P*_i).
      dsum += dist2(z, c.data()) / (H_[v] * H_[v]);
      free_ids.push_back(v);
      z_free.insert(z_free.end(), z, z + 3);
      c_free.insert(c_free.end(), c.begin(), c.end());
    }
    s.D = s.nb_free ? dsum / s.nb_free : 0.0;

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
    } else {
      // Plain relaxed Lloyd targets (kept for a restart), then the accelerated ones.
      std::vector<double> plain(z_free.size());
      const int nf = static_cast<int>(free_ids.size());
      int nb_limited = 0;
#pragma omp parallel for schedule(static, 256) reduction(+ : nb_limited)
      for (int i = 0; i < nf; ++i) {
        double goal[3];
        for (int d = 0; d < 3; ++d)
          goal[d] = z_free[3 * i + d] + o_.relaxation * (c_free[3 * i + d] - z_free[3 * i + d]);
        if (!safe_target(free_ids[i], goal, star, constrained, &plain[3 * i])) ++nb_limited;
      }
      s.nb_limited += nb_limited;
      std::vector<double> next = plain;
      if (accelerated) {
        if (free_ids != accepted_free_) mixer_.reset();
        std::vector<double> g(c_free.size());
        for (std::size_t k = 0; k < g.size(); ++k)
          g[k] = z_free[k] + o_.relaxation * (c_free[k] - z_free[k]);
        const std::vector<double> mixed = mixer_.next(z_free, g);
#pragma omp parallel for schedule(static, 256)
        for (int i = 0; i < nf; ++i)
          safe_target(free_ids[i], &mixed[3 * i], star, constrained, &next[3 * i]);
      }
      have_accepted_ = true;
      last_was_fallback_ = false;
      accepted_energy_ = s.energy;
      accepted_xyz_ = m_.xyz;
      accepted_free_ = free_ids;
      accepted_plain_ = plain;
      for (std::size_t i = 0; i < free_ids.size(); ++i)
        for (int d = 0; d < 3; ++d) target[3 * free_ids[i] + d] = next[3 * i + d];
    }
    // Move and re-triangulate.
    s.seconds_move = seconds_since(t0) - s.seconds_cells;
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
    verify_after_step();
    s.seconds_check = seconds_since(t2);
    return s;
  }

  int nb_steiner() const {
    return nb_steiner_;
  }

  // The last iteration may have left a few faces non-Delaunay or vertices short of their targets
  // (see Lloyd3Options::max_flip_leftover): rebuild the constrained Delaunay mesh of the points.
  void finish() {
    if (mesh_is_cdt_) return;
    const Delaunay3Stats ds = delaunay_->retetrahedralize(m_);
    nb_steiner_ += ds.nb_steiner;
    verify_after_step();
    mesh_is_cdt_ = true;
  }

 private:
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

  void verify_after_step() {
    const MeshCheck c = check_mesh(m_);
    if (!c.ok)
      throw InvariantError("Lloyd iteration produced an invalid mesh: " +
                           (c.problems.empty() ? std::string("?") : c.problems.front()));
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

  TetMesh& m_;
  Lloyd3Options o_;
  std::unique_ptr<Delaunay3> delaunay_;
  ConstrainedFaces constrained_set_;  // the constrained triangles never change
  bool delaunay_known_ = false;       // every unconstrained face is locally Delaunay
  bool mesh_is_cdt_ = true;           // the mesh is the constrained Delaunay one of its points
  int iteration_ = 0;
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
  const MeshCheck c = check_mesh(mesh);
  if (!c.ok) throw InvariantError("lloyd_optimize_3d: invalid input mesh: " + c.problems.front());
  // Free vertices in space order (fixed ones keep their ids): a tet's points are then close in
  // memory too.
  sort_free_vertices_spatially(mesh);
  Lloyd3Problem problem(mesh, options);
  LloydResult r = lloyd_iterate(problem, options.lloyd, progress);
  problem.finish();
  return r;
}

}  // namespace cvtmesh
