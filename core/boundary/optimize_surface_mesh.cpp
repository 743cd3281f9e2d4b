#include "core/boundary/optimize_surface_mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/flip_surface_edges.h"
#include "core/boundary/smooth_surface_vertices.h"
#include "core/geometry/vec3.h"
#include "core/quality/quality.h"

namespace cvtmesh {
namespace {

// What a round is judged by: the minimum angle, Q_min, the average Q (larger is better).
struct Score {
  double min_angle = 0, q_min = 0, q_avg = 0, max_angle = 0;
  // Not worse than `in` on any row of the quality table.
  bool no_worse_than(const Score& in) const {
    return min_angle >= in.min_angle && q_min >= in.q_min && q_avg >= in.q_avg &&
           max_angle <= in.max_angle;
  }
  // The minimum angle to 0.01 degree and Q_min to 1e-4 first: a round that raises the average
  // is not lost to a last-digit change of a minimum.
  bool operator>(const Score& o) const {
    const double a = std::floor(min_angle * 100), oa = std::floor(o.min_angle * 100);
    const double q = std::floor(q_min * 1e4), oq = std::floor(o.q_min * 1e4);
    return std::tie(a, q, q_avg) > std::tie(oa, oq, o.q_avg);
  }
};

Score score(const TetMesh& m) {
  Score s{180, 1, 0};
  int n = 0;
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* t = &m.tris[3 * f];
    if (t[0] < 0) continue;
    const double *a = m.point(t[0]), *b = m.point(t[1]), *c = m.point(t[2]);
    const double q = tri_quality(a, b, c, 3, Measure::kQ);
    s.min_angle = std::min(s.min_angle, tri_quality(a, b, c, 3, Measure::kMinAngle));
    s.max_angle = std::max(s.max_angle, tri_quality(a, b, c, 3, Measure::kMaxAngle));
    s.q_min = std::min(s.q_min, q);
    s.q_avg += q;
    ++n;
  }
  if (n) s.q_avg /= n;
  return s;
}

double mean_edge_length(const TetMesh& m) {
  double sum = 0;
  long n = 0;
  for (int f = 0; f < m.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      sum += std::sqrt(dist2(m.point(m.tris[3 * f + k]), m.point(m.tris[3 * f + (k + 1) % 3])));
      ++n;
    }
  return n ? sum / n : 0;
}

// The vertices of the worst `fraction` of the triangles (by minimum angle), worst first.
std::vector<int> worst_vertices(const TetMesh& m, double fraction) {
  std::vector<std::pair<double, int>> by_angle;
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* t = &m.tris[3 * f];
    by_angle.push_back(
        {tri_quality(m.point(t[0]), m.point(t[1]), m.point(t[2]), 3, Measure::kMinAngle), f});
  }
  std::sort(by_angle.begin(), by_angle.end());
  const std::size_t n =
      std::min(by_angle.size(),
               std::max<std::size_t>(1, static_cast<std::size_t>(fraction * by_angle.size())));
  std::vector<int> out;
  std::vector<char> seen(static_cast<std::size_t>(m.nb_vertices()), 0);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const int v = m.tris[3 * by_angle[i].second + k];
      if (!seen[v]) {
        seen[v] = 1;
        out.push_back(v);
      }
    }
  return out;
}

}  // namespace

SurfaceMeshStats optimize_surface_mesh(TetMesh& m, const BoundaryModel& model,
                                       const SurfaceMeshOptions& o) {
  SurfaceMeshStats st;
  SurfaceFlipOptions fo;
  fo.flat_angle = o.flat_angle;
  fo.coplanar_only = o.fix_vertices;
  fo.hausdorff = o.hausdorff;
  fo.kept_edges = o.kept_edges;
  const Score input_score = score(m);
  // The floors of the moves and the ceiling of the moves and flips, from the input's extremes:
  // no move or flip takes a fan below the input's minimum angle or Q_min, nor above its maximum
  // angle (each round is then not worse than the input on those rows).
  fo.max_angle_ceiling = std::min(fo.max_angle_ceiling, input_score.max_angle);
  if (o.fix_vertices) {
    st.nb_flips = flip_surface_edges(m, model, fo).nb_flipped;
    st.rounds = 1;
    st.best_round = st.nb_flips ? 1 : 0;
    st.converged = true;
    return st;
  }
  std::vector<int> all(static_cast<std::size_t>(m.nb_vertices()));
  std::iota(all.begin(), all.end(), 0);
  const double step_tolerance = o.tolerance * mean_edge_length(m);
  // The input's local sizes: each vertex's mean edge length (the CVT's density).
  std::vector<double> sizes(static_cast<std::size_t>(m.nb_vertices()), 0);
  {
    std::vector<int> count(sizes.size(), 0);
    for (int f = 0; f < m.nb_tris(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = m.tris[3 * f + k], b = m.tris[3 * f + (k + 1) % 3];
        const double l = std::sqrt(dist2(m.point(a), m.point(b)));
        sizes[a] += l;
        sizes[b] += l;
        ++count[a];
        ++count[b];
      }
    for (std::size_t v = 0; v < sizes.size(); ++v)
      if (count[v]) sizes[v] /= count[v];
  }
  TetMesh best = m;
  Score best_score = input_score;
  // The last round that gained a visible amount (0.01 degree, 1e-4 of Q_min or average Q).
  Score gain_score = input_score;
  int gain_round = 0;
  for (int round = 1; round <= o.rounds; ++round) {
    st.rounds = round;
    SurfaceMoveOptions mo;
    mo.relaxation = o.relaxation;
    mo.hausdorff = o.hausdorff;
    mo.sizes = &sizes;
    mo.q_floor = std::max(mo.q_floor, input_score.q_min);
    mo.angle_floor = std::max(mo.angle_floor, input_score.min_angle);
    mo.angle_ceiling = std::min(mo.angle_ceiling, input_score.max_angle);
    BoundaryFans fans = boundary_fans(m);
    const SurfaceMoveStats cvt = smooth_surface_vertices(m, model, fans, all, mo);
    const SurfaceFlipStats flips = flip_surface_edges(m, model, fo);
    if (flips.nb_flipped) fans = boundary_fans(m);
    mo.kind = SurfaceMoveKind::kMaxMin;
    const SurfaceMoveStats maxmin =
        smooth_surface_vertices(m, model, fans, worst_vertices(m, o.worst_fraction), mo);
    st.nb_moves += cvt.nb_moved + maxmin.nb_moved;
    st.nb_flips += flips.nb_flipped;
    const Score s = score(m);
    if (o.progress) o.progress(round, s.q_min, s.q_avg);
    if (s.no_worse_than(input_score) && s > best_score) {
      best_score = s;
      best = m;
      st.best_round = round;
      if (best_score.min_angle > gain_score.min_angle + 0.01 ||
          best_score.q_min > gain_score.q_min + 1e-4 ||
          best_score.q_avg > gain_score.q_avg + 1e-4) {
        gain_score = best_score;
        gain_round = round;
      }
    }
    // Converged: the vertices stopped and no edge flips, or no round better than the best for
    // `patience` rounds.
    if ((std::max(cvt.max_step, maxmin.max_step) <= step_tolerance && flips.nb_flipped == 0) ||
        round - gain_round >= o.patience) {
      st.converged = true;
      break;
    }
  }
  m = std::move(best);
  return st;
}

}  // namespace cvtmesh
