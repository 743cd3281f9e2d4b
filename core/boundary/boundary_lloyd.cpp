#include "core/boundary/boundary_lloyd.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <stdexcept>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/boundary_move.h"
#include "core/cvt/lloyd3.h"
#include "core/delaunay/restore_delaunay3.h"
#include "core/geometry/predicates.h"
#include "core/geometry/vec3.h"
#include "core/quality/quality.h"
#include "core/mesh/build_adjacency.h"
#include "core/mesh/vertex_tets.h"
#include "core/swap/constrained_faces.h"

namespace cvtmesh {
namespace {

// Moves interior vertex v to p if its star stays positively oriented.
bool move_interior(TetMesh& m, const VertexTets& star, int v, const double* p) {
  auto at = [&](int w) { return w == v ? p : m.point(w); };
  for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) {
    const int* w = &m.tets[4 * static_cast<std::size_t>(*t)];
    if (orient3d(at(w[0]), at(w[1]), at(w[2]), at(w[3])) <= 0) return false;
  }
  for (int d = 0; d < 3; ++d) m.point(v)[d] = p[d];
  return true;
}

// The minimum Q of v's star tets and of its fan triangles.
std::pair<double, double> star_minima(const TetMesh& m, const VertexTets& star,
                                      const BoundaryFans& fans, int v) {
  double q = 1, t = 1;
  for (const int* s = star.begin_of(v); s != star.end_of(v); ++s) {
    const int* w = &m.tets[4 * static_cast<std::size_t>(*s)];
    q = std::min(
        q, tet_quality(m.point(w[0]), m.point(w[1]), m.point(w[2]), m.point(w[3]), Measure::kQ));
  }
  for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f) {
    const int* w = &m.tris[3 * static_cast<std::size_t>(*f)];
    t = std::min(t, tri_quality(m.point(w[0]), m.point(w[1]), m.point(w[2]), 3, Measure::kQ));
  }
  return {q, t};
}

// The maximum dihedral angle (degrees) of v's star tets.
double star_max_angle(const TetMesh& m, const VertexTets& star, int v) {
  double a = 0;
  for (const int* s = star.begin_of(v); s != star.end_of(v); ++s) {
    const int* w = &m.tets[4 * static_cast<std::size_t>(*s)];
    a = std::max(a, tet_quality(m.point(w[0]), m.point(w[1]), m.point(w[2]), m.point(w[3]),
                                Measure::kMaxAngle));
  }
  return a;
}

// The paper's D over the interior vertices (vclass dim 3, with tets) of the configuration whose
// cells `cc` are, with H at the vertices from the same evaluation: the mean of |c - z|^2 / H^2
// (the full move to the centroid, as the Lloyd iteration's D).
double interior_D(const TetMesh& m, const CellCentroids& cc, const std::vector<double>& H) {
  double sum = 0;
  long n = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    if (v >= static_cast<int>(m.vclass.size()) || m.vclass[v].dim != 3 || !(cc.mass[v] > 0))
      continue;
    const double* z = m.point(v);
    const double* c = &cc.centroid[3 * static_cast<std::size_t>(v)];
    if (!std::isfinite(c[0] + c[1] + c[2])) continue;
    sum += dist2(z, c) / (H[v] * H[v]);
    ++n;
  }
  return n ? sum / n : 0;
}

}  // namespace

BoundaryLloydStats boundary_lloyd(TetMesh& mesh, const BoundaryModel& model,
                                  const SizingField3& sizing, const BoundaryLloydOptions& o) {
  if (!(o.relaxation > 0 && o.relaxation < 2) || o.max_rounds < 0 || o.max_halvings < 0)
    throw std::invalid_argument("boundary_lloyd: relaxation in (0,2), rounds and halvings >= 0");
  if (mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);
  BoundaryLloydStats stats;
  Lloyd3CellBuffers own_buffers;  // kept from round to round
  Lloyd3CellBuffers& buffers = o.cell_buffers ? *o.cell_buffers : own_buffers;
  buffers.hints.assign(mesh.nb_vertices(), -1);  // hints of another sizing field are not ours
  CellCentroids cc = voronoi_centroids_3d(mesh, sizing, buffers);
  double cc_D = interior_D(mesh, cc, buffers.H);
  stats.energy.push_back(cc.energy);
  const double h = mean_edge_length(mesh);
  double omega = o.relaxation;
  int halvings = 0;
  for (int round = 0; round < o.max_rounds;) {
    const TetMesh backup = mesh;
    const VolumeBudget budget_backup = o.volume_budget ? *o.volume_budget : VolumeBudget{};
    std::vector<double> delta;
    const VertexTets star = vertex_tets(mesh);
    const BoundaryFans fans = boundary_fans(mesh);
    long moved = 0, refused = 0, nb_boundary = 0;
    double sum_move2 = 0;
    const int nv = mesh.nb_vertices();
    auto target = [&](int v, double* wanted) {
      const double* z = mesh.point(v);
      for (int d = 0; d < 3; ++d) wanted[d] = z[d] + omega * (cc.centroid[3 * v + d] - z[d]);
    };
    // The boundary targets projected onto their entities first, in parallel: a vertex's target
    // and projection depend only on its own position and centroid, which no other move changes
    // (build/cvtmesh -v optimize /work/tmp/c1m.msh, 1M tets, 24890 boundary vertices, timers
    // around the round's parts: the projections were 0.23 s of the 1.1-1.4 s of serial moves over
    // 3 rounds; the rest reads the neighbours' moves, in vertex order).
    std::vector<double> projected(3 * static_cast<std::size_t>(nv));
    std::vector<char> has_projection(nv, 0);
#pragma omp parallel for schedule(dynamic, 256) if (model.geometry && model.geometry->thread_safe())
    for (int v = 0; v < nv; ++v)
      if (star.nb_tets_of(v) > 0 && model.movable(v)) {
        double wanted[3];
        target(v, wanted);
        has_projection[v] = project_on_entity(model, v, wanted, &projected[3 * v]);
      }
    for (int v = 0; v < nv; ++v) {
      if (star.nb_tets_of(v) == 0) continue;
      const double* z = mesh.point(v);
      if (model.movable(v)) {
        ++nb_boundary;
        const PlannedBoundaryMove plan =
            has_projection[v]
                ? check_boundary_move(mesh, model, star, fans, v, &projected[3 * v], o.hausdorff)
                : PlannedBoundaryMove{BoundaryMoveStatus::kNoProjection};
        if (plan.status != BoundaryMoveStatus::kOk) {
          ++refused;
          continue;
        }
        if (o.volume_budget && !o.volume_budget->admits(mesh, star, v, plan.position, delta)) {
          ++refused;
          continue;
        }
        const auto before = star_minima(mesh, star, fans, v);
        // The input's own curves (vclass dim 1: CAD curves, a mesh file's curve entities), not the
        // features the discrete geometry finds on a surface entity (guarding those on
        // igl_decimated-knight raised its refined runs' max dihedral by 2 degrees).
        const bool on_curve = o.curve_angle_guard < 180 &&
                              v < static_cast<int>(mesh.vclass.size()) && mesh.vclass[v].dim == 1;
        const double angle_before = on_curve ? star_max_angle(mesh, star, v) : 0;
        const Vec3 old = vec3(z);
        apply_boundary_move(mesh, v, plan);
        const auto after = star_minima(mesh, star, fans, v);
        if (after.first < std::min(before.first, o.q_guard) ||
            after.second < std::min(before.second, o.tri_guard) ||
            (on_curve &&
             star_max_angle(mesh, star, v) > std::max(angle_before, o.curve_angle_guard))) {
          for (int d = 0; d < 3; ++d) mesh.point(v)[d] = old[d];
          ++refused;
          continue;
        }
        if (o.volume_budget) o.volume_budget->commit(delta);
        double d2 = 0;
        for (int d = 0; d < 3; ++d) d2 += (plan.position[d] - old[d]) * (plan.position[d] - old[d]);
        sum_move2 += d2;
        ++moved;
      } else if (o.move_interior && v < static_cast<int>(mesh.vclass.size()) &&
                 mesh.vclass[v].dim == 3) {
        double wanted[3];
        target(v, wanted);
        move_interior(mesh, star, v, wanted);
      }
    }
    const ConstrainedFaces constrained = constrained_faces(mesh);
    restore_delaunay_by_flips(mesh, constrained, false);
    if (mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);
    CellCentroids next = voronoi_centroids_3d(mesh, sizing, buffers);
    if (next.energy > cc.energy) {
      mesh = backup;
      if (o.volume_budget) *o.volume_budget = budget_backup;
      ++stats.nb_undone;
      if (++halvings > o.max_halvings) break;
      omega *= 0.5;
      continue;
    }
    cc = std::move(next);
    cc_D = interior_D(mesh, cc, buffers.H);
    stats.energy.push_back(cc.energy);
    stats.nb_moved += moved;
    stats.nb_refused += refused;
    ++stats.rounds;
    ++round;
    const double D = nb_boundary ? sum_move2 / (nb_boundary * h * h) : 0;
    if (D < o.tolerance) break;
  }
  stats.interior_D = cc_D;
  return stats;
}

}  // namespace cvtmesh
