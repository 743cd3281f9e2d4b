#include "core/cvt/lloyd3.h"

#include <chrono>
#include <memory>

#include "core/cvt/lloyd3_anderson.h"
#include "core/cvt/lloyd3_cells.h"
#include "core/cvt/lloyd3_check.h"
#include "core/cvt/lloyd3_lbfgs.h"
#include "core/cvt/lloyd3_reinsert.h"
#include "core/cvt/move_safeguard3.h"
#include "core/delaunay/delaunay3.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/sort_tets.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// One Lloyd iteration = the cells of the current mesh (lloyd3_cells.h), the targets of the free
// vertices (L-BFGS, lloyd3_lbfgs.h, or relaxed/Anderson Lloyd, lloyd3_anderson.h; both through
// the move safeguard, move_safeguard3.h), the re-insertion (lloyd3_reinsert.h) and the check
// (lloyd3_check.h).
class Lloyd3Problem {
 public:
  Lloyd3Problem(TetMesh& mesh, const Lloyd3Options& o)
      : m_(mesh),
        o_(o),
        delaunay_(Delaunay3::create(o.backend)),
        constrained_set_(constrained_faces(mesh)),
        cells_(o.cell_buffers ? *o.cell_buffers : own_cells_),
        anderson_(o.relaxation, o.anderson_depth),
        lbfgs_(o.lbfgs_memory, o.relaxation) {
    if (o_.sizing)
      sizing_ = o_.sizing;
    else
      sizing_ = std::shared_ptr<const SizingField3>(make_mesh_sizing3(mesh).release());
    cells_.hints.assign(m_.nb_vertices(), -1);
  }

  LloydStep step() {
    LloydStep s;
    const auto t0 = Clock::now();
    // Tets in space order: the per-tet and per-star passes of the cells then hit the cache
    // (flips scatter new tets over free slots; every few iterations is enough; sorted on entry).
    if (++iteration_ % 4 == 0) sort_tets_spatially(m_);
    const Lloyd3Cells e =
        lloyd3_cells(m_, *sizing_, o_.compute_energy, faces_listed_, cells_, s, &non_delaunay_);
    s.seconds_cells = seconds_since(t0);
    const MoveSafeguard3 safe = [&](const std::vector<double>& goal, std::vector<double>& out) {
      return safe_targets3(m_, cells_.cm, e.free_ids, goal, o_.max_halvings, out);
    };
    const std::vector<double> target = o_.lbfgs_memory > 0 ? lbfgs_.targets(e, m_.xyz, safe, s)
                                                           : anderson_.targets(e, m_.xyz, safe, s);
    s.seconds_move = seconds_since(t0) - s.seconds_cells;
    move_to(target, s);
    return s;
  }

  // The end of the iteration: the last check on the whole structure. Faces the last flips left
  // non-Delaunay are not rebuilt away: they sit next to the boundary, where the constrained
  // Delaunay mesh needs Steiner points, and TetGen's rebuild ("pYAzQMO0") leaves nearly all of
  // them too (measured with restore_delaunay_by_flips after it: cube_sphere 25k 35 -> 34 faces,
  // femur 280 -> 265), for ~4 s of a single thread per Lloyd run at 1M tets.
  void finish() {
    if (!last_check_full_) verify(true);
  }

 private:
  // Moves the vertices to `target` and re-triangulates (flips, or a rebuild), then checks: the
  // whole structure every 4th iteration, after a rebuild and at the end; the orientation of
  // every tet after every move.
  void move_to(const std::vector<double>& target, LloydStep& s) {
    const auto t1 = Clock::now();
    const Reinsertion r = reinsert_vertices3(m_, constrained_set_, target, o_.local_flips,
                                             o_.max_flip_leftover, *delaunay_, s);
    faces_listed_ = r.faces_listed;
    non_delaunay_ = r.non_delaunay_faces;
    nb_steiner_ += r.nb_steiner;
    s.seconds_delaunay = seconds_since(t1);
    const auto t2 = Clock::now();
    verify(s.rebuilt || iteration_ % 4 == 0);
    s.seconds_check = seconds_since(t2);
  }

  void verify(bool full) {
    last_check_full_ = full;
    verify_lloyd3_mesh(m_, full);
  }

  TetMesh& m_;
  Lloyd3Options o_;
  std::unique_ptr<Delaunay3> delaunay_;
  ConstrainedFaces constrained_set_;  // the constrained triangles never change
  std::shared_ptr<const SizingField3> sizing_;
  Lloyd3CellBuffers own_cells_;
  Lloyd3CellBuffers& cells_;  // own_cells_ or the caller's
  AndersonLloyd3 anderson_;
  LbfgsLloyd3 lbfgs_;
  // Every unconstrained face not in non_delaunay_ is locally Delaunay (after the flips of the last
  // re-insertion): the cells test only the tets of those faces (and the constrained faces).
  bool faces_listed_ = false;
  std::vector<FaceKey> non_delaunay_;
  bool last_check_full_ = true;
  int iteration_ = 0;
  int nb_steiner_ = 0;
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
