#include "core/mesh/transfer_views.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cvtmesh {
namespace {

// The live simplices of a mesh as flat arrays: d+1 corners each, coordinates with 3 components
// (z = z0 in 2D).
struct Simplices {
  int dim = 3;
  std::vector<double> xyz;
  std::vector<int> corners;  // (dim + 1) per live simplex
  std::vector<int> live;     // element index of each live simplex
};

Simplices simplices_of(const MeshData& d) {
  Simplices s;
  s.dim = d.dim;
  if (d.dim == 3) {
    s.xyz = d.tet.xyz;
  } else {
    const std::size_t nv = d.tri.xy.size() / 2;
    s.xyz.resize(3 * nv);
    for (std::size_t v = 0; v < nv; ++v) {
      s.xyz[3 * v] = d.tri.xy[2 * v];
      s.xyz[3 * v + 1] = d.tri.xy[2 * v + 1];
      s.xyz[3 * v + 2] = 0;
    }
  }
  const std::vector<int>& cells = d.dim == 3 ? d.tet.tets : d.tri.tris;
  const int npe = d.dim + 1;
  for (std::size_t c = 0; c * npe < cells.size(); ++c)
    if (cells[npe * c] >= 0) {
      s.corners.insert(s.corners.end(), &cells[npe * c], &cells[npe * c] + npe);
      s.live.push_back(static_cast<int>(c));
    }
  return s;
}

// Barycentric coordinates of x in simplex k (dim + 1 of them; negative outside).
void barycentric(const Simplices& s, int k, const double* x, double* w) {
  const int* c = &s.corners[(s.dim + 1) * k];
  const double* p0 = &s.xyz[3 * c[0]];
  if (s.dim == 2) {
    const double* p1 = &s.xyz[3 * c[1]];
    const double* p2 = &s.xyz[3 * c[2]];
    const double det = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]);
    const double a = ((x[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (x[1] - p0[1])) / det;
    const double b = ((p1[0] - p0[0]) * (x[1] - p0[1]) - (x[0] - p0[0]) * (p1[1] - p0[1])) / det;
    w[0] = 1 - a - b;
    w[1] = a;
    w[2] = b;
    return;
  }
  double e[3][3], r[3];
  for (int i = 0; i < 3; ++i) {
    for (int k2 = 0; k2 < 3; ++k2) e[i][k2] = s.xyz[3 * c[i + 1] + k2] - p0[k2];
    r[i] = x[i] - p0[i];
  }
  // Solve [e0 e1 e2] (columns) * (w1, w2, w3) = r by Cramer's rule.
  auto det3 = [](const double* a, const double* b, const double* c3) {
    return a[0] * (b[1] * c3[2] - b[2] * c3[1]) - a[1] * (b[0] * c3[2] - b[2] * c3[0]) +
           a[2] * (b[0] * c3[1] - b[1] * c3[0]);
  };
  const double det = det3(e[0], e[1], e[2]);
  w[1] = det3(r, e[1], e[2]) / det;
  w[2] = det3(e[0], r, e[2]) / det;
  w[3] = det3(e[0], e[1], r) / det;
  w[0] = 1 - w[1] - w[2] - w[3];
}

// A uniform grid over the simplices' bounding boxes: the simplices overlapping each cell.
class SimplexGrid {
 public:
  explicit SimplexGrid(const Simplices& s) : s_(s) {
    const int nk = static_cast<int>(s.live.size());
    const int npe = s.dim + 1;
    for (int k = 0; k < 3; ++k) {
      lo_[k] = std::numeric_limits<double>::max();
      hi_[k] = std::numeric_limits<double>::lowest();
    }
    for (int v : s.corners)
      for (int k = 0; k < 3; ++k) {
        lo_[k] = std::min(lo_[k], s.xyz[3 * v + k]);
        hi_[k] = std::max(hi_[k], s.xyz[3 * v + k]);
      }
    double measure = 1;
    for (int k = 0; k < s.dim; ++k) measure *= std::max(hi_[k] - lo_[k], 1e-300);
    const double h = std::pow(measure / std::max(nk, 1), 1.0 / s.dim);
    for (int k = 0; k < 3; ++k) {
      n_[k] = k < s.dim ? std::clamp(static_cast<int>((hi_[k] - lo_[k]) / h) + 1, 1, 1 << 10) : 1;
      inv_[k] = n_[k] / std::max(hi_[k] - lo_[k], 1e-300);
    }
    start_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1, 0);
    auto range = [&](int k, int lo[3], int hi[3]) {
      double a[3], b[3];
      for (int i = 0; i < 3; ++i) {
        a[i] = std::numeric_limits<double>::max();
        b[i] = std::numeric_limits<double>::lowest();
      }
      for (int j = 0; j < npe; ++j)
        for (int i = 0; i < 3; ++i) {
          a[i] = std::min(a[i], s.xyz[3 * s.corners[npe * k + j] + i]);
          b[i] = std::max(b[i], s.xyz[3 * s.corners[npe * k + j] + i]);
        }
      for (int i = 0; i < 3; ++i) {
        lo[i] = cell(i, a[i]);
        hi[i] = cell(i, b[i]);
      }
    };
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<std::size_t> fill;
      if (pass == 1) {
        for (std::size_t g = 1; g < start_.size(); ++g) start_[g] += start_[g - 1];
        items_.resize(start_.back());
        fill.assign(start_.begin(), start_.end() - 1);
      }
      for (int k = 0; k < nk; ++k) {
        int lo[3], hi[3];
        range(k, lo, hi);
        for (int i = lo[0]; i <= hi[0]; ++i)
          for (int j = lo[1]; j <= hi[1]; ++j)
            for (int l = lo[2]; l <= hi[2]; ++l) {
              const std::size_t g = index(i, j, l);
              if (pass == 0)
                ++start_[g + 1];
              else
                items_[fill[g]++] = k;
            }
      }
    }
  }

  // The simplex holding x (barycentric weights in w), or the best one near it (weights clamped).
  int locate(const double* x, double* w) const {
    int c[3];
    for (int i = 0; i < 3; ++i) c[i] = cell(i, x[i]);
    int best = -1;
    double best_min = -std::numeric_limits<double>::max();
    double tmp[4];
    const int nmax = std::max({n_[0], n_[1], n_[2]});
    for (int ring = 0; ring <= nmax; ++ring) {
      for (int i = c[0] - ring; i <= c[0] + ring; ++i)
        for (int j = c[1] - ring; j <= c[1] + ring; ++j)
          for (int l = c[2] - ring; l <= c[2] + ring; ++l) {
            if (std::max({std::abs(i - c[0]), std::abs(j - c[1]), std::abs(l - c[2])}) != ring)
              continue;  // only the ring's shell
            if (i < 0 || j < 0 || l < 0 || i >= n_[0] || j >= n_[1] || l >= n_[2]) continue;
            const std::size_t g = index(i, j, l);
            for (std::size_t q = start_[g]; q < start_[g + 1]; ++q) {
              const int k = items_[q];
              barycentric(s_, k, x, tmp);
              double m = tmp[0];
              for (int t = 1; t <= s_.dim; ++t) m = std::min(m, tmp[t]);
              if (std::isfinite(m) && m > best_min) {
                best_min = m;
                best = k;
                std::copy(tmp, tmp + s_.dim + 1, w);
              }
            }
          }
      // Inside one (up to rounding), or the nearest found after one more ring.
      if (best >= 0 && (best_min >= -1e-12 || ring >= 1)) break;
    }
    if (best >= 0 && best_min < 0) {
      double sum = 0;
      for (int t = 0; t <= s_.dim; ++t) sum += w[t] = std::max(w[t], 0.0);
      for (int t = 0; t <= s_.dim; ++t) w[t] /= sum;
    }
    return best;
  }

 private:
  int cell(int i, double x) const {
    return std::clamp(static_cast<int>((x - lo_[i]) * inv_[i]), 0, n_[i] - 1);
  }
  std::size_t index(int i, int j, int l) const {
    return (static_cast<std::size_t>(l) * n_[1] + j) * n_[0] + i;
  }
  const Simplices& s_;
  double lo_[3], hi_[3], inv_[3];
  int n_[3];
  std::vector<std::size_t> start_;
  std::vector<int> items_;
};

}  // namespace

std::vector<DataView> transfer_views(const MeshData& from, const MeshData& to) {
  std::vector<DataView> out;
  if (from.dim != to.dim) return out;
  const std::uint64_t source = mesh_fingerprint(from), target = mesh_fingerprint(to);
  bool any = false;
  for (const DataView& v : from.model().views) any |= v.fingerprint == source;
  if (!any) return out;
  const Simplices a = simplices_of(from), b = simplices_of(to);
  if (a.live.empty()) return out;
  const SimplexGrid grid(a);
  const int npe = a.dim + 1;
  // The simplex of `from` (its live index) and the weights for every vertex of `to`, and the
  // simplex of `from` for every live simplex of `to` (its centroid).
  const long nv = static_cast<long>(b.xyz.size() / 3), nc = static_cast<long>(b.live.size());
  std::vector<int> vertex_in(nv, -1), cell_in(nc, -1);
  std::vector<double> weights(static_cast<std::size_t>(nv) * npe, 0);
  std::vector<char> used(nv, 0);
  for (int v : b.corners) used[v] = 1;
#pragma omp parallel for schedule(dynamic, 256)
  for (long v = 0; v < nv; ++v)
    if (used[v]) vertex_in[v] = grid.locate(&b.xyz[3 * v], &weights[npe * v]);
#pragma omp parallel for schedule(dynamic, 256)
  for (long k = 0; k < nc; ++k) {
    double x[3] = {0, 0, 0}, w[4];
    for (int j = 0; j < npe; ++j)
      for (int i = 0; i < 3; ++i) x[i] += b.xyz[3 * b.corners[npe * k + j] + i] / npe;
    cell_in[k] = grid.locate(x, w);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const DataView& v : from.model().views) {
    if (v.fingerprint != source) continue;
    DataView t;
    t.name = v.name;
    t.on_nodes = v.on_nodes;
    t.components = v.components;
    t.times = v.times;
    t.fingerprint = target;
    const int nc_ = v.components;
    for (const std::vector<double>& step : v.steps) {
      std::vector<double> values;
      if (v.on_nodes) {
        values.assign(static_cast<std::size_t>(nv) * nc_, nan);
        for (long p = 0; p < nv; ++p) {
          if (vertex_in[p] < 0) continue;
          const int* c = &a.corners[npe * vertex_in[p]];
          for (int i = 0; i < nc_; ++i) {
            double sum = 0;
            for (int j = 0; j < npe; ++j) {
              const double w = weights[npe * p + j];
              const double x = step[static_cast<std::size_t>(c[j]) * nc_ + i];
              if (w != 0) sum += w * x;
            }
            values[static_cast<std::size_t>(p) * nc_ + i] = sum;
          }
        }
      } else {
        values.assign(static_cast<std::size_t>(nc) * nc_, nan);
        for (long k = 0; k < nc; ++k) {
          if (cell_in[k] < 0) continue;
          const std::size_t src = static_cast<std::size_t>(cell_in[k]);  // live index in from
          for (int i = 0; i < nc_; ++i)
            values[static_cast<std::size_t>(k) * nc_ + i] = step[src * nc_ + i];
        }
      }
      t.steps.push_back(std::move(values));
    }
    out.push_back(std::move(t));
  }
  return out;
}

}  // namespace cvtmesh
