#include "core/smoothing/improve_local2d.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/geometry/predicates.h"
#include "core/quality/quality.h"
#include "core/swap/flip2d_pass.h"

namespace cvtmesh {
namespace {

struct StarMeasure {
  bool valid = false;
  double q_min = 2, q_sum = 0, a_min = 180, a_max = 0;
};

class VertexMover {
 public:
  VertexMover(TriMesh2& mesh, const std::vector<char>& fixed) : m_(mesh) {
    const int nv = m_.nb_vertices(), nt = m_.nb_tris();
    std::vector<char> held(nv, 0);
    for (int v : m_.edges) held[v] = 1;
    for (int t = 0; t < nt; ++t)
      if (m_.tris[3 * t] >= 0)
        for (int e = 0; e < 3; ++e)
          if (m_.adj[3 * t + e] < 0)
            held[m_.tris[3 * t + (e + 1) % 3]] = held[m_.tris[3 * t + (e + 2) % 3]] = 1;
    std::vector<char> used(nv, 0);
    for (int t = 0; t < nt; ++t)
      if (m_.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k) used[m_.tris[3 * t + k]] = 1;
    for (int v = 0; v < nv; ++v)
      if (used[v] && !held[v] && m_.vclass[v].dim == 2 &&
          (fixed.empty() || !fixed[static_cast<std::size_t>(v)]))
        free_.push_back(v);
  }

  int nb_free() const { return static_cast<int>(free_.size()); }

  // One sweep over the free vertices that are active (all at first; then those whose star
  // changed since they were last tried: a neighbour moved, or a flip touched it); returns the
  // number of accepted moves.
  long sweep() {
    build_stars();
    if (active_.empty()) active_.assign(m_.nb_vertices(), 1);
    std::vector<char> next(m_.nb_vertices(), 0);
    long moves = 0;
    for (int v : free_) {
      if (!active_[v]) continue;
      if (!move(v)) continue;
      ++moves;
      for (int k = start_[v]; k < start_[v + 1]; ++k)
        for (int j = 0; j < 3; ++j) next[m_.tris[3 * around_[k] + j]] = 1;
    }
    // A vertex moved after a neighbour of it was tried this sweep is tried again next sweep.
    active_.swap(next);
    return moves;
  }

  // The vertices of triangles a flip pass changed are tried again.
  void activate(const std::vector<int>& tris_before) {
    if (active_.empty()) return;  // every vertex is active on the first sweep
    for (std::size_t t = 0; 3 * t < m_.tris.size(); ++t)
      if (!std::equal(&m_.tris[3 * t], &m_.tris[3 * t] + 3, &tris_before[3 * t]))
        for (int j = 0; j < 3; ++j)
          active_[m_.tris[3 * t + j]] = active_[tris_before[3 * t + j]] = 1;
  }

 private:
  void build_stars() {
    const int nv = m_.nb_vertices(), nt = m_.nb_tris();
    start_.assign(nv + 1, 0);
    for (int t = 0; t < nt; ++t)
      if (m_.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k) ++start_[m_.tris[3 * t + k] + 1];
    for (int v = 0; v < nv; ++v) start_[v + 1] += start_[v];
    around_.resize(start_[nv]);
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    for (int t = 0; t < nt; ++t)
      if (m_.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k) around_[fill[m_.tris[3 * t + k]]++] = t;
  }

  // The star of v with v at p. bound: the measure a candidate must not fall below
  // (acceptable()'s minima and maximum angle); the first triangle below it ends the measure,
  // invalid (acceptable() would refuse it: the measure of an acceptable star is complete).
  StarMeasure measure(int v, const double* p, const StarMeasure* bound = nullptr) const {
    StarMeasure s;
    for (int k = start_[v]; k < start_[v + 1]; ++k) {
      const int* tv = &m_.tris[3 * around_[k]];
      std::array<const double*, 3> x;
      for (int j = 0; j < 3; ++j) x[j] = tv[j] == v ? p : m_.point(tv[j]);
      if (orient2d(x[0], x[1], x[2]) <= 0) return s;
      const double q = tri_quality(x[0], x[1], x[2], 2, Measure::kQ);
      if (bound && q < bound->q_min) return s;
      s.q_min = std::min(s.q_min, q);
      s.q_sum += q;
      const auto [lo, hi] = tri_min_max_angle(x[0], x[1], x[2], 2);
      if (bound && (lo < bound->a_min || hi > bound->a_max)) return s;
      s.a_min = std::min(s.a_min, lo);
      s.a_max = std::max(s.a_max, hi);
    }
    s.valid = true;
    return s;
  }

  static bool acceptable(const StarMeasure& s, const StarMeasure& old) {
    return s.valid && s.q_min >= old.q_min && s.a_min >= old.a_min && s.a_max <= old.a_max &&
           s.q_sum > old.q_sum * (1 + 1e-12);
  }

  bool move(int v) {
    if (start_[v + 1] - start_[v] < 3) return false;
    const double* p = m_.point(v);
    const StarMeasure old = measure(v, p);
    if (!old.valid) return false;
    // The Laplacian position and the area-weighted centroid of the star.
    double lap[2] = {0, 0}, cen[2] = {0, 0}, area = 0,
           shortest = std::numeric_limits<double>::max();
    int nb = 0;
    for (int k = start_[v]; k < start_[v + 1]; ++k) {
      const int* tv = &m_.tris[3 * around_[k]];
      const double* a = m_.point(tv[0]);
      const double* b = m_.point(tv[1]);
      const double* c = m_.point(tv[2]);
      const double ar = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
      cen[0] += ar * (a[0] + b[0] + c[0]) / 3;
      cen[1] += ar * (a[1] + b[1] + c[1]) / 3;
      area += ar;
      for (int j = 0; j < 3; ++j)
        if (tv[j] != v) {
          const double* u = m_.point(tv[j]);
          lap[0] += u[0];
          lap[1] += u[1];
          ++nb;
          shortest = std::min(shortest, std::hypot(u[0] - p[0], u[1] - p[1]));
        }
    }
    if (nb == 0 || area <= 0) return false;
    lap[0] /= nb;
    lap[1] /= nb;
    cen[0] /= area;
    cen[1] /= area;
    double best[2] = {p[0], p[1]};
    StarMeasure best_s = old;
    bool found = false;
    auto consider = [&](double x, double y) {
      const double q[2] = {x, y};
      const StarMeasure s = measure(v, q, &old);
      if (acceptable(s, old) && s.q_sum > best_s.q_sum) {
        best_s = s;
        best[0] = x;
        best[1] = y;
        found = true;
      }
    };
    for (const double* target : {lap, cen})
      for (double f : {1.0, 0.5, 0.25})
        consider(p[0] + f * (target[0] - p[0]), p[1] + f * (target[1] - p[1]));
    // Compass search from the best position so far.
    double step = 0.1 * shortest;
    for (int h = 0; h <= 6; ++h, step *= 0.5) {
      bool improved = true;
      for (int it = 0; improved && it < 4; ++it) {  // at most 4 steps of one length
        improved = false;
        const double cx = best[0], cy = best[1];
        for (int d = 0; d < 8; ++d) {
          const double ang = d * 0.7853981633974483;
          const double before = best_s.q_sum;
          consider(cx + step * std::cos(ang), cy + step * std::sin(ang));
          if (best_s.q_sum > before) improved = true;
        }
      }
    }
    if (!found) return false;
    double* w = m_.point(v);
    w[0] = best[0];
    w[1] = best[1];
    return true;
  }

  TriMesh2& m_;
  std::vector<int> free_, start_, around_;
  std::vector<char> active_;
};

}  // namespace

ImproveLocal2dStats improve_local2d(TriMesh2& mesh, const std::vector<char>& fixed,
                                    const ImproveLocal2dOptions& options) {
  ImproveLocal2dStats st;
  VertexMover mover(mesh, fixed);
  st.nb_free = mover.nb_free();
  for (int r = 0; r < options.max_rounds; ++r) {
    const std::vector<int> tris_before = mesh.tris;
    const long flips = flip2d_pass(mesh, {.criterion = FlipCriterion2d::kNoWorse});
    if (flips) mover.activate(tris_before);
    const long moves = mover.sweep();
    st.nb_flips += flips;
    st.nb_moves += moves;
    st.rounds = r + 1;
    if (flips == 0 && moves == 0) break;
  }
  return st;
}

}  // namespace cvtmesh
