#include "core/cvt/sizing_field2d.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "core/util/error.h"

namespace cvtmesh {
namespace {

double dist(const double* a, const double* b) {
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

// Mean length of the constrained edges (all edges if there are none).
double mean_boundary_edge(const TriMesh2& m) {
  double sum = 0;
  long n = 0;
  for (int e = 0; e < m.nb_edges(); ++e, ++n)
    sum += dist(m.point(m.edges[2 * e]), m.point(m.edges[2 * e + 1]));
  if (n == 0)
    for (int t = 0; t < m.nb_tris(); ++t)
      if (m.tris[3 * t] >= 0)
        for (int k = 0; k < 3; ++k, ++n)
          sum += dist(m.point(m.tris[3 * t + k]), m.point(m.tris[3 * t + (k + 1) % 3]));
  return n ? sum / static_cast<double>(n) : 1.0;
}

// A vertex's mean edge length varies by some percent from vertex to vertex even where the mesh
// follows a smooth size: `passes` Jacobi passes average each interior vertex's size with its
// neighbours'. A vertex on a constrained edge takes the mean of its constrained edges instead
// (the boundary's spacing, which a smoothing pass would bias towards the interior's sizes).
void smooth_vertex_sizes(const TriMesh2& bg, int passes, std::vector<double>& h) {
  const int nv = bg.nb_vertices();
  std::vector<double> bsum(nv, 0);
  std::vector<int> bcnt(nv, 0);
  for (int e = 0; e < bg.nb_edges(); ++e) {
    const int a = bg.edges[2 * e], b = bg.edges[2 * e + 1];
    const double l = dist(bg.point(a), bg.point(b));
    bsum[a] += l, bsum[b] += l, ++bcnt[a], ++bcnt[b];
  }
  for (int v = 0; v < nv; ++v)
    if (bcnt[v]) h[v] = bsum[v] / bcnt[v];
  std::vector<std::pair<int, int>> nb;  // (vertex, neighbour), each edge both ways
  for (int t = 0; t < bg.nb_tris(); ++t) {
    const int* tv = &bg.tris[3 * t];
    if (tv[0] < 0) continue;
    for (int k = 0; k < 3; ++k) {
      nb.push_back({tv[k], tv[(k + 1) % 3]});
      nb.push_back({tv[(k + 1) % 3], tv[k]});
    }
  }
  std::sort(nb.begin(), nb.end());
  nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
  std::vector<double> next(nv), sum(nv);
  std::vector<int> cnt(nv);
  for (int p = 0; p < passes; ++p) {
    std::fill(sum.begin(), sum.end(), 0.0);
    std::fill(cnt.begin(), cnt.end(), 0);
    for (const auto& [v, w] : nb) sum[v] += h[w], ++cnt[v];
    for (int v = 0; v < nv; ++v)
      next[v] = bcnt[v] || !cnt[v] ? h[v] : 0.5 * h[v] + 0.5 * sum[v] / cnt[v];
    h.swap(next);
  }
}

}  // namespace

SizingField2d::SizingField2d(const TriMesh2& mesh, const SizingField2dOptions& o) {
  if (o.kind == "uniform") {
    kind_ = Kind::kUniform;
    h_ = o.h > 0 ? o.h : mean_boundary_edge(mesh);
    return;
  }
  if (o.kind == "function") {
    if (!o.function) throw std::invalid_argument("sizing \"function\" needs a size function");
    kind_ = Kind::kFunction;
    function_ = o.function;
    return;
  }
  if (o.kind != "mesh")
    throw std::invalid_argument("unknown sizing \"" + o.kind + "\" (uniform, function or mesh)");
  kind_ = Kind::kMesh;
  const TriMesh2& bg = o.background ? *o.background : mesh;
  const std::vector<double>& bg_xy_ = bg.xy;
  std::vector<int> bg_tris_, bg_adj_;
  std::vector<double> bg_h_;
  const int nv = bg.nb_vertices();
  std::vector<double> sum(nv, 0);
  std::vector<int> cnt(nv, 0);
  for (int t = 0; t < bg.nb_tris(); ++t) {
    const int* tv = &bg.tris[3 * t];
    if (tv[0] < 0) continue;
    bg_tris_.insert(bg_tris_.end(), tv, tv + 3);
    for (int k = 0; k < 3; ++k) {
      // Each interior edge is seen twice (once per side), boundary edges once: a mean over the
      // incident triangles' edges, which is what a P1 size should reproduce.
      const int a = tv[k], b = tv[(k + 1) % 3];
      const double l = dist(bg.point(a), bg.point(b));
      sum[a] += l, sum[b] += l, ++cnt[a], ++cnt[b];
    }
  }
  if (bg_tris_.empty()) throw InputError("sizing from a mesh: the mesh has no triangles");
  bg_h_.resize(nv);
  for (int v = 0; v < nv; ++v) bg_h_[v] = cnt[v] ? sum[v] / cnt[v] : 0;
  if (o.smoothing_passes > 0) smooth_vertex_sizes(bg, o.smoothing_passes, bg_h_);
  // Triangle neighbours (across the edge opposite each corner) for the walk in size().
  {
    const int ntri = static_cast<int>(bg_tris_.size() / 3);
    bg_adj_.assign(bg_tris_.size(), -1);
    std::unordered_map<std::uint64_t, int> open;  // directed edge (a, b) -> 3 t + k
    open.reserve(bg_tris_.size());
    auto key = [](int a, int b) {
      return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
             static_cast<std::uint32_t>(b);
    };
    for (int t = 0; t < ntri; ++t)
      for (int k = 0; k < 3; ++k) {
        const int a = bg_tris_[3 * t + (k + 1) % 3], b = bg_tris_[3 * t + (k + 2) % 3];
        const auto it = open.find(key(b, a));
        if (it != open.end()) {
          bg_adj_[3 * t + k] = it->second / 3;
          bg_adj_[it->second] = t;
          open.erase(it);
        } else {
          open.emplace(key(a, b), 3 * t + k);
        }
      }
  }
  // Bucket grid of about one triangle per cell.
  const int nt = static_cast<int>(bg_tris_.size() / 3);
  double hi[2] = {-std::numeric_limits<double>::infinity(),
                  -std::numeric_limits<double>::infinity()};
  lo_[0] = lo_[1] = std::numeric_limits<double>::infinity();
  for (int v : bg_tris_)
    for (int k = 0; k < 2; ++k) {
      lo_[k] = std::min(lo_[k], bg_xy_[2 * v + k]);
      hi[k] = std::max(hi[k], bg_xy_[2 * v + k]);
    }
  const double w = std::max(hi[0] - lo_[0], 1e-300), hgt = std::max(hi[1] - lo_[1], 1e-300);
  const double side = std::sqrt(w * hgt / nt);
  nx_ = std::clamp(static_cast<int>(w / side) + 1, 1, 4096);
  ny_ = std::clamp(static_cast<int>(hgt / side) + 1, 1, 4096);
  cell_[0] = w / nx_ * (1 + 1e-12), cell_[1] = hgt / ny_ * (1 + 1e-12);
  auto cell_range = [&](int t, int r[4]) {
    double blo[2] = {std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::infinity()};
    double bhi[2] = {-blo[0], -blo[1]};
    for (int k = 0; k < 3; ++k)
      for (int d = 0; d < 2; ++d) {
        blo[d] = std::min(blo[d], bg_xy_[2 * bg_tris_[3 * t + k] + d]);
        bhi[d] = std::max(bhi[d], bg_xy_[2 * bg_tris_[3 * t + k] + d]);
      }
    r[0] = std::clamp(static_cast<int>((blo[0] - lo_[0]) / cell_[0]), 0, nx_ - 1);
    r[1] = std::clamp(static_cast<int>((bhi[0] - lo_[0]) / cell_[0]), 0, nx_ - 1);
    r[2] = std::clamp(static_cast<int>((blo[1] - lo_[1]) / cell_[1]), 0, ny_ - 1);
    r[3] = std::clamp(static_cast<int>((bhi[1] - lo_[1]) / cell_[1]), 0, ny_ - 1);
  };
  bucket_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  int r[4];
  for (int t = 0; t < nt; ++t) {
    cell_range(t, r);
    for (int j = r[2]; j <= r[3]; ++j)
      for (int i = r[0]; i <= r[1]; ++i) ++bucket_start_[j * nx_ + i + 1];
  }
  for (std::size_t c = 1; c < bucket_start_.size(); ++c) bucket_start_[c] += bucket_start_[c - 1];
  bucket_tris_.resize(bucket_start_.back());
  std::vector<int> fill(bucket_start_.begin(), bucket_start_.end() - 1);
  for (int t = 0; t < nt; ++t) {
    cell_range(t, r);
    for (int j = r[2]; j <= r[3]; ++j)
      for (int i = r[0]; i <= r[1]; ++i) bucket_tris_[fill[j * nx_ + i]++] = t;
  }
  bg_.resize(nt);
  for (int t = 0; t < nt; ++t) {
    const int* tv = &bg_tris_[3 * t];
    const double* a = &bg_xy_[2 * tv[0]];
    const double* b = &bg_xy_[2 * tv[1]];
    const double* d = &bg_xy_[2 * tv[2]];
    BgTri& g = bg_[t];
    g.a[0] = a[0], g.a[1] = a[1];
    g.e1[0] = b[0] - a[0], g.e1[1] = b[1] - a[1];
    g.e2[0] = d[0] - a[0], g.e2[1] = d[1] - a[1];
    g.det = g.e1[0] * g.e2[1] - g.e1[1] * g.e2[0];
    for (int k = 0; k < 3; ++k) g.h[k] = bg_h_[tv[k]], g.adj[k] = bg_adj_[3 * t + k];
  }
}

double SizingField2d::size(const double* x) const {
  // The quadrature points of one Voronoi piece lie close together: the walk starts from the
  // background triangle that last held a point strictly inside (per thread).
  thread_local const SizingField2d* hint_owner = nullptr;
  thread_local int hint = -1;
  if (hint_owner != this) hint_owner = this, hint = -1;
  return size(x, hint);
}

double SizingField2d::size_scan(const double* x, int& hint) const {
  if (kind_ == Kind::kUniform) return h_;
  if (kind_ == Kind::kFunction) {
    const double h = function_(x);
    if (!(h > 0) || !std::isfinite(h))
      throw InputError("size function returned " + std::to_string(h) + " at (" +
                       std::to_string(x[0]) + ", " + std::to_string(x[1]) + "); it must be > 0");
    return h;
  }
  // P1 interpolation in the background triangle containing x (the best candidate of the
  // nearest non-empty bucket ring if x is outside every triangle). A point strictly inside one
  // triangle is inside no other, so size()'s walk returns the value this scan would (the scan's
  // best is that triangle).
  const int ci = std::clamp(static_cast<int>((x[0] - lo_[0]) / cell_[0]), 0, nx_ - 1);
  const int cj = std::clamp(static_cast<int>((x[1] - lo_[1]) / cell_[1]), 0, ny_ - 1);
  double best = -std::numeric_limits<double>::infinity(), value = 0;
  for (int ring = 0; ring < std::max(nx_, ny_); ++ring) {
    for (int j = std::max(0, cj - ring); j <= std::min(ny_ - 1, cj + ring); ++j)
      for (int i = std::max(0, ci - ring); i <= std::min(nx_ - 1, ci + ring); ++i) {
        if (std::max(std::abs(i - ci), std::abs(j - cj)) != ring) continue;
        const int c = j * nx_ + i;
        for (int k = bucket_start_[c]; k < bucket_start_[c + 1]; ++k) {
          const int t = bucket_tris_[k];
          double l[3];
          if (!barycentric(t, x, l)) continue;
          const double m = std::min({l[0], l[1], l[2]});
          if (m <= best) continue;
          best = m;
          value = interpolate(t, l);
          if (m > 0) {
            hint = t;
            return value;
          }
        }
      }
    if (best >= -1e-12 || (best > -std::numeric_limits<double>::infinity() && ring >= 1)) break;
  }
  return value;
}

}  // namespace cvtmesh
