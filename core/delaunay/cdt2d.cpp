#include "core/delaunay/cdt2d.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <numeric>
#include <string>
#include <unordered_set>
#include <utility>

#include "core/delaunay/cdt2d_locate.h"
#include "core/geometry/predicates.h"
#include "core/mesh/edge_index.h"
#include "core/mesh/face_key.h"
#include "core/mesh/tri_mesh2.h"
#include "core/swap/flip2d.h"
#include "core/swap/flip2d_delaunay.h"
#include "core/swap/flip2d_pass.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

// Position along a Hilbert curve of (x, y) in [0, 2^16)^2 (for a spatially coherent insertion
// order: short walks).
std::uint64_t hilbert_key(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = 1u << 15; s > 0; s >>= 1) {
    const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
    d += static_cast<std::uint64_t>(s) * s * ((3 * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) x = s - 1 - x, y = s - 1 - y;
      std::swap(x, y);
    }
  }
  return d;
}

class Builder {
 public:
  explicit Builder(const std::vector<double>& xy) : n_(static_cast<int>(xy.size() / 2)) {
    m_.xy = xy;
    double lo[2] = {0, 0}, hi[2] = {1, 1};
    if (n_ > 0) {
      lo[0] = hi[0] = xy[0], lo[1] = hi[1] = xy[1];
      for (int i = 1; i < n_; ++i)
        for (int k = 0; k < 2; ++k) {
          lo[k] = std::min(lo[k], xy[2 * i + k]);
          hi[k] = std::max(hi[k], xy[2 * i + k]);
        }
    }
    for (int k = 0; k < 2; ++k) lo_[k] = lo[k], ext_[k] = hi[k] - lo[k];
    const double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
    double r = std::max(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(r > 0)) r = std::max(1.0, std::fabs(cx) + std::fabs(cy));
    const double big = 100.0 * r, s3 = std::sqrt(3.0);
    m_.xy.insert(m_.xy.end(), {cx, cy + 2 * big, cx - s3 * big, cy - big, cx + s3 * big, cy - big});
    m_.tris = {n_, n_ + 1, n_ + 2};
    m_.adj = {-1, -1, -1};
    vtri_.assign(n_ + 3, 0);
  }

  void insert_all() {
    std::vector<int> order(n_);
    std::iota(order.begin(), order.end(), 0);
    std::vector<std::uint64_t> key(n_);
    for (int i = 0; i < n_; ++i) {
      std::uint32_t q[2];
      for (int k = 0; k < 2; ++k) {
        const double u = ext_[k] > 0 ? (m_.xy[2 * i + k] - lo_[k]) / ext_[k] : 0.0;
        q[k] = static_cast<std::uint32_t>(std::clamp(u, 0.0, 1.0) * 65535.0);
      }
      key[i] = hilbert_key(q[0], q[1]);
    }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
    int hint = 0;
    for (int v : order) hint = insert(v, hint);
  }

  void recover(const std::vector<int>& segments) {
    std::deque<std::pair<int, int>> work;
    for (std::size_t s = 0; 2 * s + 1 < segments.size(); ++s) {
      const int a = segments[2 * s], b = segments[2 * s + 1];
      if (a < 0 || a >= n_ || b < 0 || b >= n_)
        throw InputError("cdt2d: segment " + std::to_string(s) + " has a vertex id out of range");
      if (a == b) throw InputError("cdt2d: segment " + std::to_string(s) + " has zero length");
      work.push_back({a, b});
    }
    while (!work.empty()) {
      const auto [a, b] = work.front();
      work.pop_front();
      if (constrained_.count(edge_key(a, b))) continue;
      int split = -1;
      if (!recover_one(a, b, &split)) {
        work.push_front({split, b});
        work.push_front({a, split});
        continue;
      }
      constrained_.insert(edge_key(a, b));
      out_segments_.insert(out_segments_.end(), {a, b});
    }
    // Restore the Delaunay property away from the segments. Without a recovery flip the
    // triangulation is the insertion's, Delaunay already (Lawson's flips leave every edge
    // locally Delaunay): the pass would flip nothing.
    m_.edges = out_segments_;
    if (recovery_flips_ > 0) flip2d_pass(m_);
  }

  Cdt2dResult finish() {
    Cdt2dResult r;
    const int nt = m_.nb_tris();
    r.nb_points = n_;
    r.component.assign(nt, -2);
    std::vector<char> cons(3 * static_cast<std::size_t>(nt), 0);
    const EdgeIndex segments(out_segments_, m_.nb_vertices());  // the edges of constrained_
    for (int t = 0; t < nt; ++t)
      for (int e = 0; e < 3; ++e) {
        const int* tv = &m_.tris[3 * t];
        cons[3 * t + e] = segments.contains(tv[(e + 1) % 3], tv[(e + 2) % 3]);
      }
    auto flood = [&](int seed, int id) {
      std::vector<int> stack{seed};
      r.component[seed] = id;
      while (!stack.empty()) {
        const int t = stack.back();
        stack.pop_back();
        for (int e = 0; e < 3; ++e) {
          const int o = m_.adj[3 * t + e];
          if (o < 0 || cons[3 * t + e] || r.component[o / 3] != -2) continue;
          r.component[o / 3] = id;
          stack.push_back(o / 3);
        }
      }
    };
    for (int t = 0; t < nt; ++t)
      if (r.component[t] == -2 && *std::max_element(&m_.tris[3 * t], &m_.tris[3 * t] + 3) >= n_)
        flood(t, -1);
    for (int t = 0; t < nt; ++t)
      if (r.component[t] == -2) flood(t, r.nb_components++);
    r.xy = std::move(m_.xy);
    r.tris = std::move(m_.tris);
    r.adj = std::move(m_.adj);
    r.segments = std::move(out_segments_);
    return r;
  }

 private:
  // Triangles (v, ring[k], ring[k+1]) around a new vertex v; outer[k] is the slot across
  // (ring[k], ring[k+1]); slots[k] is the triangle to (re)use.
  void make_fan(int v, const std::vector<int>& ring, const std::vector<int>& outer,
                const std::vector<int>& tri_ids) {
    const int k = static_cast<int>(ring.size());
    for (int i = 0; i < k; ++i) {
      const int t = tri_ids[i];
      m_.tris[3 * t] = v, m_.tris[3 * t + 1] = ring[i], m_.tris[3 * t + 2] = ring[(i + 1) % k];
      m_.adj[3 * t] = outer[i];
      if (outer[i] >= 0) m_.adj[outer[i]] = 3 * t;
      m_.adj[3 * t + 1] = 3 * tri_ids[(i + 1) % k] + 2;
      m_.adj[3 * t + 2] = 3 * tri_ids[(i + k - 1) % k] + 1;
      vtri_[ring[i]] = t;
    }
    vtri_[v] = tri_ids[0];
  }

  int new_tri() {
    m_.tris.insert(m_.tris.end(), {-1, -1, -1});
    m_.adj.insert(m_.adj.end(), {-1, -1, -1});
    return m_.nb_tris() - 1;
  }

  int insert(int v, int hint) {
    const double* p = m_.point(v);
    const Locate2dResult loc = locate2d(m_, p, hint);
    if (loc.tri < 0) throw InvariantError("cdt2d: point location failed");
    if (loc.on_vertex >= 0)
      throw InputError(
          "the 2D Delaunay triangulation cannot take two vertices at the same "
          "place (vertices " +
          std::to_string(loc.on_vertex) + " and " + std::to_string(v) + ", 0-based, at (" +
          std::to_string(p[0]) + ", " + std::to_string(p[1]) +
          "); e.g. a crack's duplicated nodes)");
    const int t = loc.tri;
    std::vector<int>& ring = ring_;
    std::vector<int>& outer = outer_;
    std::vector<int>& ids = ids_;
    if (loc.on_edge < 0) {
      const int a = m_.tris[3 * t], b = m_.tris[3 * t + 1], c = m_.tris[3 * t + 2];
      ring = {b, c, a};
      outer = {m_.adj[3 * t], m_.adj[3 * t + 1], m_.adj[3 * t + 2]};
      const int t1 = new_tri(), t2 = new_tri();
      ids = {t, t1, t2};
    } else {
      const int e = loc.on_edge;
      const int o = m_.adj[3 * t + e];
      if (o < 0) throw InvariantError("cdt2d: point on the super-triangle's boundary");
      const int t2 = o / 3, e2 = o % 3;
      const int c = m_.tris[3 * t + e], a = m_.tris[3 * t + (e + 1) % 3],
                b = m_.tris[3 * t + (e + 2) % 3], d = m_.tris[3 * t2 + e2];
      ring = {c, a, d, b};
      outer = {m_.adj[3 * t + (e + 2) % 3], m_.adj[3 * t2 + (e2 + 1) % 3],
               m_.adj[3 * t2 + (e2 + 2) % 3], m_.adj[3 * t + (e + 1) % 3]};
      const int t3 = new_tri(), t4 = new_tri();
      ids = {t, t2, t3, t4};
    }
    make_fan(v, ring, outer, ids);
    // Lawson flips: examine the edges opposite v.
    std::vector<int>& stack = stack_;
    stack.clear();
    for (int t2 : ids) stack.push_back(3 * t2);
    while (!stack.empty()) {
      const int s = stack.back();
      stack.pop_back();
      if (m_.tris[s] != v || is_locally_delaunay2d(m_, s)) continue;
      const int t1 = s / 3, t2 = m_.adj[s] / 3;
      if (!flip2d(m_, s)) continue;  // a non-convex quadrilateral is always locally Delaunay
      note_flip(t1, t2);
      stack.push_back(3 * t1);      // t1 = (v, a, d): edge (a, d) opposite v
      stack.push_back(3 * t2 + 2);  // t2 = (d, b, v): edge (d, b) opposite v
    }
    return vtri_[v];
  }

  void note_flip(int t1, int t2) {
    for (int k = 0; k < 3; ++k) vtri_[m_.tris[3 * t1 + k]] = t1;
    vtri_[m_.tris[3 * t2 + 1]] = t2;  // (d, b, c): b left t1
  }

  // The triangles around vertex u, in counter-clockwise order as far as possible.
  std::vector<int> star(int u) const {
    std::vector<int> s;
    const int t0 = vtri_[u];
    int t = t0;
    auto local = [&](int tt) {
      for (int k = 0; k < 3; ++k)
        if (m_.tris[3 * tt + k] == u) return k;
      throw InvariantError("cdt2d: vertex-to-triangle map is stale");
    };
    do {
      s.push_back(t);
      const int o = m_.adj[3 * t + (local(t) + 1) % 3];
      if (o < 0) break;
      t = o / 3;
    } while (t != t0);
    if (t == t0 && s.size() > 1) return s;
    t = t0;
    while (true) {
      const int o = m_.adj[3 * t + (local(t) + 2) % 3];
      if (o < 0 || o / 3 == t0) break;
      t = o / 3;
      s.push_back(t);
    }
    return s;
  }

  int find_edge(int u, int w) const {
    for (int t : star(u))
      for (int k = 0; k < 3; ++k)
        if (m_.tris[3 * t + k] == u) {
          if (m_.tris[3 * t + (k + 1) % 3] == w) return 3 * t + (k + 2) % 3;
          if (m_.tris[3 * t + (k + 2) % 3] == w) return 3 * t + (k + 1) % 3;
        }
    return -1;
  }

  double orient(int a, int b, int c) const {
    return orient2d(m_.point(a), m_.point(b), m_.point(c));
  }

  // Makes (a, b) an edge by flips. Returns false with *split set if a vertex lies on the open
  // segment (a, b): the caller recovers (a, split) and (split, b) instead.
  bool recover_one(int a, int b, int* split) {
    if (find_edge(a, b) >= 0) return true;
    const double* pa = m_.point(a);
    const double* pb = m_.point(b);
    auto ahead = [&](int x) {
      const double* px = m_.point(x);
      return (px[0] - pa[0]) * (pb[0] - pa[0]) + (px[1] - pa[1]) * (pb[1] - pa[1]) > 0;
    };
    // The triangle around a whose wedge contains the direction to b.
    int slot = -1, L = -1, R = -1;
    for (int t : star(a)) {
      int k = 0;
      while (m_.tris[3 * t + k] != a) ++k;
      const int u = m_.tris[3 * t + (k + 1) % 3], w = m_.tris[3 * t + (k + 2) % 3];
      for (int x : {u, w})
        if (x < n_ && orient(a, b, x) == 0 && ahead(x)) {
          *split = x;
          return false;
        }
      if (orient(a, u, b) > 0 && orient(a, w, b) < 0) {
        slot = 3 * t + k, R = u, L = w;
        break;
      }
    }
    if (slot < 0) throw InvariantError("cdt2d: segment recovery found no starting triangle");
    // Walk along (a, b), collecting the edges it crosses.
    std::deque<std::pair<int, int>> crossing;
    while (true) {
      if (constrained_.count(edge_key(L, R)))
        throw InputError("cdt2d: segments (" + std::to_string(a) + ", " + std::to_string(b) +
                         ") and (" + std::to_string(L) + ", " + std::to_string(R) + ") cross");
      crossing.push_back({L, R});
      const int o = m_.adj[slot];
      if (o < 0) throw InvariantError("cdt2d: segment recovery left the triangulation");
      const int t2 = o / 3;
      const int x = m_.tris[o];
      if (x == b) break;
      const double s = orient(a, b, x);
      if (s == 0) {
        *split = x;
        return false;
      }
      const int drop = s > 0 ? L : R;
      (s > 0 ? L : R) = x;
      int k = 0;
      while (m_.tris[3 * t2 + k] != drop) ++k;
      slot = 3 * t2 + k;
    }
    // Flip crossing edges away (Sloan): a crossing edge whose quadrilateral is convex is flipped;
    // if its new diagonal still crosses (a, b) it goes back in the queue.
    long guard = 0;
    const long cap = 1000 + 50L * static_cast<long>(crossing.size() * crossing.size());
    while (!crossing.empty()) {
      if (++guard > cap) throw InvariantError("cdt2d: segment recovery does not terminate");
      const auto [u, w] = crossing.front();
      crossing.pop_front();
      const int s = find_edge(u, w);
      if (s < 0) throw InvariantError("cdt2d: lost a crossing edge during recovery");
      const int t1 = s / 3, t2 = m_.adj[s] / 3;
      if (!flip2d(m_, s)) {
        crossing.push_back({u, w});
        continue;
      }
      ++recovery_flips_;
      note_flip(t1, t2);
      const int c = m_.tris[3 * t1], d = m_.tris[3 * t1 + 2];
      if (edge_key(c, d) == edge_key(a, b)) continue;
      const double oc = orient(a, b, c), od = orient(a, b, d);
      if ((oc > 0 && od < 0) || (oc < 0 && od > 0)) crossing.push_back({c, d});
    }
    return true;
  }

  int n_;
  double lo_[2], ext_[2];
  TriMesh2 m_;             // working triangulation (xy includes the super-triangle)
  std::vector<int> vtri_;  // a triangle incident to each vertex
  std::unordered_set<EdgeKey, EdgeKeyHash> constrained_;
  std::vector<int> out_segments_;
  long recovery_flips_ = 0;                      // flips made by recover_one
  std::vector<int> ring_, outer_, ids_, stack_;  // insert()'s buffers (no allocation per point)
};

}  // namespace

Cdt2dResult cdt2d(const std::vector<double>& xy, const std::vector<int>& segments) {
  if (xy.size() % 2 != 0) throw InputError("cdt2d: coordinate array has odd length");
  Builder b(xy);
  b.insert_all();
  b.recover(segments);
  return b.finish();
}

void cdt2d_and_delaunay(const std::vector<double>& xy, const std::vector<int>& segments,
                        Cdt2dResult& constrained, Cdt2dResult& delaunay) {
  if (xy.size() % 2 != 0) throw InputError("cdt2d: coordinate array has odd length");
  Builder b(xy);
  b.insert_all();
  Builder u = b;  // the same insertion, then each recovers its own segments
  u.recover({});
  delaunay = u.finish();
  b.recover(segments);
  constrained = b.finish();
}

}  // namespace cvtmesh
