#include "core/smoothing/smooth_quads2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/mesh/check_quads2d.h"
#include "core/mesh/kept_quads.h"
#include "core/quality/quad_angles.h"
#include "core/quality/quad_scaled_jacobian.h"
#include "core/quality/quality.h"

namespace cvtmesh {
namespace {

// What counts as a rise of the star's minimum / sum of scaled Jacobians (not a bound on what
// is kept: the extrema never fall).
constexpr double kGain = 1e-9, kSumGain = 1e-4;

// The star of a vertex at some position: validity and the accept rule's extrema.
struct StarMeasure {
  bool valid = false;
  double sj_min = 0, sj_sum = 0, qa_min = 360, qa_max = 0;  // quadrangles
  double tq_min = 2, tq_sum = 0, ta_min = 180, ta_max = 0;  // triangles
};

// A vertex's elements: the quadrangles (k >= 0) and triangles (-1 - t).
struct Stars {
  std::vector<int> start, elements;
};

class QuadSmoother {
 public:
  QuadSmoother(TriMesh2& mesh, const SmoothQuads2dOptions& o)
      : m_(mesh), o_(o), q_(kept_quads(mesh)) {
    const int nv = m_.nb_vertices();
    stars_.start.assign(nv + 1, 0);
    for (int v : q_.quads) ++stars_.start[v + 1];
    for (int t = 0; t < m_.nb_tris(); ++t)
      if (m_.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k) ++stars_.start[m_.tris[3 * t + k] + 1];
    for (int v = 0; v < nv; ++v) stars_.start[v + 1] += stars_.start[v];
    stars_.elements.resize(stars_.start[nv]);
    std::vector<int> fill(stars_.start.begin(), stars_.start.end() - 1);
    for (int k = 0; k < q_.nb_quads(); ++k)
      for (int j = 0; j < 4; ++j) stars_.elements[fill[q_.quads[4 * k + j]]++] = k;
    for (int t = 0; t < m_.nb_tris(); ++t)
      if (m_.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k) stars_.elements[fill[m_.tris[3 * t + k]]++] = -1 - t;
    // Free: in a quadrangle, inside a surface, on no line and no kept line or point, its star
    // closed (every edge at the vertex in exactly two of its elements).
    std::vector<char> fixed(nv, 0);
    for (int e = 0; e < m_.nb_edges(); ++e)
      if (m_.edge_curve[e] >= 0) fixed[m_.edges[2 * e]] = fixed[m_.edges[2 * e + 1]] = 1;
    for (const ElementBlock& b : m_.model.extra)
      if (b.dim < 2)
        for (int v : b.nodes) fixed[v] = 1;
    std::vector<char> in_quad(nv, 0);
    for (int v : q_.quads) in_quad[v] = 1;
    for (int v = 0; v < nv; ++v)
      if (in_quad[v] && !fixed[v] && m_.vclass[v].dim == 2 && m_.vclass[v].entity >= 0 &&
          closed_star(v))
        free_.push_back(v);
  }

  const std::vector<int>& free_vertices() const { return free_; }

  // Flags v and the vertices of its elements.
  void mark_star(int v, std::vector<char>& flag) const {
    for (int i = stars_.start[v]; i < stars_.start[v + 1]; ++i) {
      int n = 0;
      const int* ev = element(stars_.elements[i], n);
      for (int j = 0; j < n; ++j) flag[ev[j]] = 1;
    }
  }

  // One move of v, if one is accepted. Returns whether v moved.
  bool smooth(int v) {
    double* p = m_.point(v);
    const double x0[2] = {p[0], p[1]};
    old_sj_.clear();
    old_convex_.clear();
    const StarMeasure old = measure(v, x0, true);
    // Candidates: the Laplacian position, the mean of the elements' centroids; each a whole,
    // half and quarter step.
    double lap[2] = {0, 0}, cen[2] = {0, 0};
    int nlap = 0, ncen = 0;
    double shortest = std::numeric_limits<double>::infinity();
    for (int i = stars_.start[v]; i < stars_.start[v + 1]; ++i) {
      int n = 0;
      const int* ev = element(stars_.elements[i], n);
      int at = 0;
      while (ev[at] != v) ++at;
      for (int s : {1, n - 1}) {
        const double* w = m_.point(ev[(at + s) % n]);
        lap[0] += w[0], lap[1] += w[1], ++nlap;
        shortest = std::min(shortest, std::hypot(w[0] - x0[0], w[1] - x0[1]));
      }
      for (int j = 0; j < n; ++j)
        cen[0] += m_.point(ev[j])[0] / n, cen[1] += m_.point(ev[j])[1] / n;
      ++ncen;
    }
    lap[0] /= nlap, lap[1] /= nlap, cen[0] /= ncen, cen[1] /= ncen;
    StarMeasure best = old;
    double bx[2] = {x0[0], x0[1]};
    bool found = false;
    auto consider = [&](double x, double y) {
      const double c[2] = {x, y};
      const StarMeasure s = measure(v, c, false);
      if (accepted(old, s) && better(s, best)) {
        best = s, bx[0] = x, bx[1] = y, found = true;
        return true;
      }
      return false;
    };
    for (const double* g : {lap, cen})
      for (double f : {1.0, 0.5, 0.25})
        consider(x0[0] + f * (g[0] - x0[0]), x0[1] + f * (g[1] - x0[1]));
    // Compass search from the best position on the star's minimum, where that is below
    // compass_below.
    double h = 0.1 * shortest;
    const int halvings = old.sj_min < o_.compass_below ? o_.compass_halvings : -1;
    for (int halving = 0, steps = 0; halving <= halvings && steps < 64; ++steps) {
      bool moved = false;
      for (int d = 0; d < 8 && !moved; ++d) {
        const double a = d * M_PI / 4;
        const double from[2] = {bx[0], bx[1]};
        moved = consider(from[0] + h * std::cos(a), from[1] + h * std::sin(a));
      }
      if (!moved) h *= 0.5, ++halving;
    }
    p[0] = found ? bx[0] : x0[0];
    p[1] = found ? bx[1] : x0[1];
    return found;
  }

 private:
  const int* element(int e, int& n) const {
    if (e >= 0) {
      n = 4;
      return &q_.quads[4 * e];
    }
    n = 3;
    return &m_.tris[3 * (-1 - e)];
  }

  bool closed_star(int v) const {
    std::map<int, int> count;  // neighbour -> elements holding the edge
    for (int i = stars_.start[v]; i < stars_.start[v + 1]; ++i) {
      int n = 0;
      const int* ev = element(stars_.elements[i], n);
      int at = 0;
      while (ev[at] != v) ++at;
      ++count[ev[(at + 1) % n]];
      ++count[ev[(at + n - 1) % n]];
    }
    for (const auto& [w, c] : count)
      if (c != 2) return false;
    return !count.empty();
  }

  // The star of v with v at x (the mesh is left with v at x: the caller restores it).
  // `record`: the quadrangles' scaled Jacobians kept as the "before" values.
  StarMeasure measure(int v, const double* x, bool record) {
    double* p = m_.point(v);
    p[0] = x[0], p[1] = x[1];
    StarMeasure s;
    s.valid = true;
    s.sj_min = std::numeric_limits<double>::infinity();
    int iq = 0;
    for (int i = stars_.start[v]; i < stars_.start[v + 1]; ++i) {
      const int e = stars_.elements[i];
      int n = 0;
      const int* ev = element(e, n);
      const double *a = m_.point(ev[0]), *b = m_.point(ev[1]), *c = m_.point(ev[2]);
      if (n == 4) {
        const double* d = m_.point(ev[3]);
        const double sj = quad_scaled_jacobian(a, b, c, d);
        if (record) {
          old_sj_.push_back(sj);
          old_convex_.push_back(quad_strictly_convex(a, b, c, d));
        } else if (old_convex_[iq] ? !quad_strictly_convex(a, b, c, d) : sj < old_sj_[iq]) {
          s.valid = false;
        }
        ++iq;
        s.sj_min = std::min(s.sj_min, sj);
        s.sj_sum += sj;
        const QuadAngles qa = quad_angles(a, b, c, d);
        s.qa_min = std::min(s.qa_min, qa.min);
        s.qa_max = std::max(s.qa_max, qa.max);
      } else {
        if (orient2d(a, b, c) <= 0) s.valid = false;
        const double q = tri_quality(a, b, c, 2, Measure::kQ);
        s.tq_min = std::min(s.tq_min, q);
        s.tq_sum += q;
        const auto [lo, hi] = tri_min_max_angle(a, b, c, 2);
        s.ta_min = std::min(s.ta_min, lo);
        s.ta_max = std::max(s.ta_max, hi);
      }
    }
    return s;
  }

  bool accepted(const StarMeasure& o, const StarMeasure& n) const {
    if (!n.valid) return false;
    if (n.sj_min < o.sj_min || (o_.guard_sum && n.sj_sum < o.sj_sum) || n.qa_min < o.qa_min ||
        n.qa_max > o.qa_max)
      return false;
    if (n.tq_min < o.tq_min || n.tq_sum < o.tq_sum || n.ta_min < o.ta_min || n.ta_max > o.ta_max)
      return false;
    return n.sj_min > o.sj_min + kGain || n.sj_sum > o.sj_sum + kSumGain;
  }

  static bool better(const StarMeasure& a, const StarMeasure& b) {
    if (a.sj_min > b.sj_min + kGain) return true;
    return a.sj_min >= b.sj_min - kGain && a.sj_sum > b.sj_sum + kSumGain;
  }

  TriMesh2& m_;
  SmoothQuads2dOptions o_;
  KeptQuads q_;
  Stars stars_;
  std::vector<int> free_;
  std::vector<double> old_sj_;
  std::vector<char> old_convex_;
};

// The sum of the quadrangles' scaled Jacobians, in kept_quads order (quality_stats's).
double sum_scaled_jacobians(const TriMesh2& m) {
  const KeptQuads q = kept_quads(m);
  double sum = 0;
  for (int k = 0; k < q.nb_quads(); ++k) {
    const int* v = &q.quads[4 * k];
    sum += quad_scaled_jacobian(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
  }
  return sum;
}

SmoothQuads2dStats run_passes(TriMesh2& mesh, const SmoothQuads2dOptions& options) {
  SmoothQuads2dStats st;
  QuadSmoother s(mesh, options);
  st.nb_free = static_cast<int>(s.free_vertices().size());
  // A vertex is tried again in the next pass only if it or a vertex of its star moved.
  std::vector<char> active(mesh.nb_vertices(), 1), next(mesh.nb_vertices(), 0);
  for (int pass = 0; pass < options.max_passes && st.nb_free > 0; ++pass) {
    ++st.passes;
    long moved = 0;
    std::fill(next.begin(), next.end(), 0);
    for (int v : s.free_vertices()) {
      if (!active[v] || !s.smooth(v)) continue;
      ++moved;
      s.mark_star(v, next);
    }
    st.nb_moves += moved;
    active.swap(next);
    if (moved == 0) break;
  }
  return st;
}

}  // namespace

SmoothQuads2dStats smooth_quads2d(TriMesh2& mesh, const SmoothQuads2dOptions& options) {
  if (kept_quads(mesh).nb_quads() == 0) return {};
  if (options.guard_sum) return run_passes(mesh, options);
  const double before = sum_scaled_jacobians(mesh);
  TriMesh2 trial = mesh;
  const SmoothQuads2dStats st = run_passes(trial, options);
  if (sum_scaled_jacobians(trial) >= before) {
    mesh = std::move(trial);
    return st;
  }
  SmoothQuads2dOptions guarded = options;
  guarded.guard_sum = true;
  SmoothQuads2dStats g = run_passes(mesh, guarded);
  g.sum_guarded = true;
  return g;
}

}  // namespace cvtmesh
