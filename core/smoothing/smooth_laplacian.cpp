#include "core/smoothing/smooth_laplacian.h"

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/mesh/colour_vertices.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {
namespace {

double quality_of(const TetMesh& mesh, int t, Measure m) {
  const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
  return tet_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]), m);
}

}  // namespace

SmoothStats smooth_laplacian(TetMesh& mesh, const SmoothOptions& options) {
  if (options.measure == Measure::kMaxAngle)
    throw std::invalid_argument("smooth_laplacian: measure 'max-angle' is not larger-is-better");
  if (options.passes < 0) throw std::invalid_argument("smooth_laplacian: passes must be >= 0");
  const int nv = mesh.nb_vertices(), nt = mesh.nb_tets();
  const VertexTets star = vertex_tets(mesh);
  std::vector<double> q(static_cast<std::size_t>(nt), std::numeric_limits<double>::infinity());
#pragma omp parallel for schedule(static, 1024) if (nt > 1024)
  for (int t = 0; t < nt; ++t)
    if (mesh.tets[4 * static_cast<std::size_t>(t)] >= 0)
      q[t] = quality_of(mesh, t, options.measure);
  SmoothStats stats;
  stats.min_before = nt ? *std::min_element(q.begin(), q.end()) : 0;

  // Multi-colour Gauss-Seidel: the interior vertices are coloured greedily in vertex order so
  // that no two vertices of a colour share a tet; the vertices of one colour then move
  // independently (each reads its neighbours, of other colours, and writes its own point and the
  // qualities of its own star), in parallel, and the result does not depend on the thread count.
  std::vector<int> order;
  for (int v = 0; v < nv; ++v)
    if (mesh.vclass[v].dim == 3 && star.nb_tets_of(v) > 0) order.push_back(v);
  const VertexColouring colours = colour_vertices(nv, order, [&](int v, std::vector<int>& out) {
    for (const int* t = star.begin_of(v); t != star.end_of(v); ++t)
      out.insert(out.end(), &mesh.tets[4 * static_cast<std::size_t>(*t)],
                 &mesh.tets[4 * static_cast<std::size_t>(*t)] + 4);
  });
  const std::vector<int>& colour_offset = colours.offset;
  const std::vector<int>& by_colour = colours.vertices;
  const int nb_colours = colours.nb_colours();
  long nb_moved = 0, nb_half = 0, nb_rejected = 0;
  // The nodal sums of the time-step guard, updated after each colour from its accepted moves
  // (in vertex order: the same sums whatever the thread count).
  const bool guard = options.dt_guard.on;
  VertexTimeSteps steps;
  if (guard) steps = vertex_time_steps(mesh);
  // Each tet's element time step (the guard's), kept current as its star's moves are accepted.
  std::vector<double> tdt;
  if (guard) {
    tdt.assign(static_cast<std::size_t>(nt), std::numeric_limits<double>::infinity());
#pragma omp parallel for schedule(static, 1024) if (nt > 1024)
    for (int t = 0; t < nt; ++t)
      if (mesh.tets[4 * static_cast<std::size_t>(t)] >= 0)
        tdt[t] = quality_of(mesh, t, Measure::kTimeStep);
  }
  std::vector<VertexStepChange> changes;
  std::vector<char> changed;
  std::vector<std::array<double, 3>> origin;  // of the accepted moves
  for (int pass = 0; pass < options.passes; ++pass) {
    ++stats.passes;
    for (int c = 0; c < nb_colours; ++c) {
      if (guard) {
        changes.resize(static_cast<std::size_t>(colour_offset[c + 1] - colour_offset[c]));
        changed.assign(changes.size(), 0);
        origin.resize(changes.size());
      }
      // Small colours (coarse meshes) run on one thread: a fork/join per colour would cost more.
#pragma omp parallel reduction(+ : nb_moved, nb_half, nb_rejected) if (colour_offset[c + 1] - colour_offset[c] > 2048)
      {
        std::vector<int> nbrs;
        std::vector<double> new_q, new_dt;
        VertexStepChange before, after;
#pragma omp for schedule(static, 256)
        for (int i = colour_offset[c]; i < colour_offset[c + 1]; ++i) {
          const int v = by_colour[i];
          // The adjacent vertices: the other vertices of the star.
          nbrs.clear();
          double old_min = std::numeric_limits<double>::infinity();
          for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) {
            old_min = std::min(old_min, q[*t]);
            for (int k = 0; k < 4; ++k) {
              const int w = mesh.tets[4 * static_cast<std::size_t>(*t) + k];
              if (w != v) nbrs.push_back(w);
            }
          }
          std::sort(nbrs.begin(), nbrs.end());
          nbrs.erase(std::unique(nbrs.begin(), nbrs.end()), nbrs.end());
          double target[3] = {0, 0, 0};
          for (int w : nbrs)
            for (int k = 0; k < 3; ++k) target[k] += mesh.point(w)[k];
          for (int k = 0; k < 3; ++k) target[k] /= static_cast<double>(nbrs.size());

          double* P = mesh.point(v);
          const double orig[3] = {P[0], P[1], P[2]};
          double old_dt = std::numeric_limits<double>::infinity();
          if (guard)
            for (const int* t = star.begin_of(v); t != star.end_of(v); ++t)
              old_dt = std::min(old_dt, tdt[*t]);
          // The star's nodal terms before the move, taken when a trial first passes the Q test
          // (most trials that fail it never need them).
          bool have_before = false;
          auto take_before = [&] {
            if (have_before) return;
            const double trial[3] = {P[0], P[1], P[2]};
            for (int k = 0; k < 3; ++k) P[k] = orig[k];
            before.clear();
            for (const int* t = star.begin_of(v); t != star.end_of(v); ++t)
              before.add(mesh, &mesh.tets[4 * static_cast<std::size_t>(*t)], -1);
            for (int k = 0; k < 3; ++k) P[k] = trial[k];
            have_before = true;
          };
          bool moved = false;
          for (int attempt = 0; attempt < (options.half_step ? 2 : 1) && !moved; ++attempt) {
            const double s = attempt == 0 ? 1.0 : 0.5;
            for (int k = 0; k < 3; ++k) P[k] = orig[k] + s * (target[k] - orig[k]);
            new_q.clear();
            bool ok = true;
            double new_min = std::numeric_limits<double>::infinity();
            // Refused at the first tet below the star's old minimum (or not positive).
            for (const int* t = star.begin_of(v); t != star.end_of(v) && ok; ++t) {
              const int* tv = &mesh.tets[4 * static_cast<std::size_t>(*t)];
              if (orient3d(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]),
                           mesh.point(tv[3])) <= 0) {
                ok = false;
                break;
              }
              new_q.push_back(quality_of(mesh, *t, options.measure));
              new_min = std::min(new_min, new_q.back());
              if (new_min < old_min) break;
            }
            if (ok && new_min >= old_min && guard) {
              take_before();
              new_dt.clear();
              double new_min_dt = std::numeric_limits<double>::infinity();
              for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) {
                new_dt.push_back(quality_of(mesh, *t, Measure::kTimeStep));
                new_min_dt = std::min(new_min_dt, new_dt.back());
              }
              ok = time_step_allows(options.dt_guard, old_dt, new_min_dt);
              if (ok) {
                after = before;
                for (const int* t = star.begin_of(v); t != star.end_of(v); ++t)
                  after.add(mesh, &mesh.tets[4 * static_cast<std::size_t>(*t)], +1);
                ok = after.allows(options.dt_guard, steps);
                if (ok) {
                  changes[i - colour_offset[c]] = after;
                  changed[i - colour_offset[c]] = 1;
                  origin[i - colour_offset[c]] = {orig[0], orig[1], orig[2]};
                  changed[i - colour_offset[c]] = attempt == 0 ? 1 : 2;
                }
              }
            }
            if (ok && new_min >= old_min) {
              moved = true;
              std::size_t j = 0;
              for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) q[*t] = new_q[j++];
              j = 0;
              if (guard)
                for (const int* t = star.begin_of(v); t != star.end_of(v); ++t)
                  tdt[*t] = new_dt[j++];
              ++(attempt == 0 ? nb_moved : nb_half);
            }
          }
          if (!moved) {
            for (int k = 0; k < 3; ++k) P[k] = orig[k];
            ++nb_rejected;
          }
        }
      }
      if (guard)
        // Each move was judged on the sums before the colour; two moves of a colour may change
        // the sums of a common neighbour. Re-judged here one by one, in vertex order, on the
        // sums with the earlier ones applied: a move that now fails is undone (its star's tets
        // are not changed by the colour's other moves, so its Q guard still holds).
        for (std::size_t j = 0; j < changes.size(); ++j) {
          if (!changed[j]) continue;
          if (changes[j].allows(options.dt_guard, steps)) {
            changes[j].apply(steps);
            continue;
          }
          const int v = by_colour[colour_offset[c] + static_cast<int>(j)];
          for (int k = 0; k < 3; ++k) mesh.point(v)[k] = origin[j][k];
          for (const int* t = star.begin_of(v); t != star.end_of(v); ++t) {
            q[*t] = quality_of(mesh, *t, options.measure);
            tdt[*t] = quality_of(mesh, *t, Measure::kTimeStep);
          }
          ++nb_rejected;
          --(changed[j] == 1 ? nb_moved : nb_half);
        }
    }
  }
  stats.nb_moved = nb_moved;
  stats.nb_half = nb_half;
  stats.nb_rejected = nb_rejected;
  stats.min_after = nt ? *std::min_element(q.begin(), q.end()) : 0;
  return stats;
}

}  // namespace cvtmesh
