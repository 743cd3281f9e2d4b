#include "core/cvt/sizing_field3.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/vec3.h"
#include "core/mesh/face_key.h"
#include "core/mesh/locate_point.h"

namespace cvtmesh {

std::vector<EdgeKey> unique_edges(const TetMesh& m) {
  std::vector<EdgeKey> edges;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    for (const auto& e : kTetEdge) edges.push_back(edge_key(v[e[0]], v[e[1]]));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

namespace {

class Uniform final : public SizingField3 {
 public:
  explicit Uniform(double h) : h_(h) {}
  double eval(const double*, double g[3], int*) const override {
    g[0] = g[1] = g[2] = 0;
    return h_;
  }

 private:
  double h_;
};

class Function final : public SizingField3 {
 public:
  Function(std::function<double(const double*)> f, double dx) : f_(std::move(f)), dx_(dx) {}
  double eval(const double* x, double g[3], int*) const override {
    for (int k = 0; k < 3; ++k) {
      double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
      xp[k] += dx_;
      xm[k] -= dx_;
      g[k] = (f_(xp) - f_(xm)) / (2 * dx_);
    }
    return f_(x);
  }
  bool thread_safe() const override { return false; }

 private:
  std::function<double(const double*)> f_;
  double dx_;
};

class Background final : public SizingField3 {
 public:
  explicit Background(const TetMesh& m) : mesh_(m) {
    const int nv = m.nb_vertices();
    std::vector<double> sum(nv, 0);
    std::vector<int> cnt(nv, 0);
    for (int t = 0; t < m.nb_tets(); ++t) {
      const int* v = &m.tets[4 * t];
      if (v[0] < 0) continue;
      for (const auto& e : kTetEdge) {
        // Each edge is seen by several tets; the weights cancel in the mean well enough, but
        // count each (tet, edge) pair so the mean favours edges with many tets equally.
        const double l = std::sqrt(dist2(m.point(v[e[0]]), m.point(v[e[1]])));
        sum[v[e[0]]] += l;
        sum[v[e[1]]] += l;
        ++cnt[v[e[0]]];
        ++cnt[v[e[1]]];
      }
    }
    h_.resize(nv);
    double fallback = 0;
    int n = 0;
    for (int i = 0; i < nv; ++i)
      if (cnt[i]) {
        h_[i] = sum[i] / cnt[i];
        fallback += h_[i];
        ++n;
      }
    fallback = n ? fallback / n : 1.0;
    for (int i = 0; i < nv; ++i)
      if (!cnt[i]) h_[i] = fallback;
    // The raw local edge lengths of an unoptimized mesh are noisy, and rho = 1/H^5 amplifies the
    // noise: smooth H by a few Jacobi passes over the edges, keeping the grading.
    const std::vector<EdgeKey> edges = unique_edges(m);
    for (int pass = 0; pass < 4; ++pass) {
      std::vector<double> acc(h_), n(nv, 1.0);
      for (const auto& e : edges) {
        acc[e[0]] += h_[e[1]];
        acc[e[1]] += h_[e[0]];
        n[e[0]] += 1;
        n[e[1]] += 1;
      }
      for (int i = 0; i < nv; ++i) h_[i] = acc[i] / n[i];
    }
    for (int t = 0; t < m.nb_tets(); ++t)
      if (m.tets[4 * t] >= 0) {
        first_tet_ = t;
        break;
      }
  }

  double eval(const double* x, double g[3], int* hint) const override {
    int start = hint && *hint >= 0 && *hint < mesh_.nb_tets() && mesh_.tets[4 * *hint] >= 0
                    ? *hint
                    : first_tet_;
    const LocateResult r = locate_point(mesh_, x, start, nullptr, 20000);
    const int t = r.tet;
    if (hint) *hint = t;
    double w[4];
    barycentric(mesh_, t, x, w);
    if (r.status != LocateStatus::kInside) {
      // Outside the background mesh: clamp to the last tet.
      double s = 0;
      for (double& wi : w) {
        wi = std::max(0.0, wi);
        s += wi;
      }
      for (double& wi : w) wi = s > 0 ? wi / s : 0.25;
    }
    const int* v = &mesh_.tets[4 * t];
    double h = 0;
    for (int k = 0; k < 4; ++k) h += w[k] * h_[v[k]];
    // Gradient of the linear interpolant: solve with the edge matrix.
    const double* p0 = mesh_.point(v[0]);
    double E[3][3], rhs[3];
    for (int k = 0; k < 3; ++k) {
      const double* pk = mesh_.point(v[k + 1]);
      for (int d = 0; d < 3; ++d) E[k][d] = pk[d] - p0[d];
      rhs[k] = h_[v[k + 1]] - h_[v[0]];
    }
    const double det = E[0][0] * (E[1][1] * E[2][2] - E[1][2] * E[2][1]) -
                       E[0][1] * (E[1][0] * E[2][2] - E[1][2] * E[2][0]) +
                       E[0][2] * (E[1][0] * E[2][1] - E[1][1] * E[2][0]);
    if (det == 0) {
      g[0] = g[1] = g[2] = 0;
      return h;
    }
    // Cramer's rule for E g = rhs.
    for (int c = 0; c < 3; ++c) {
      double M[3][3];
      for (int r2 = 0; r2 < 3; ++r2)
        for (int d = 0; d < 3; ++d) M[r2][d] = d == c ? rhs[r2] : E[r2][d];
      g[c] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) -
              M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
              M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
             det;
    }
    return h;
  }

 private:
  TetMesh mesh_;
  std::vector<double> h_;
  int first_tet_ = 0;
};

}  // namespace

std::unique_ptr<SizingField3> make_uniform_sizing3(double h) {
  return std::make_unique<Uniform>(h);
}
std::unique_ptr<SizingField3> make_function_sizing3(std::function<double(const double*)> f,
                                                    double dx) {
  return std::make_unique<Function>(std::move(f), dx);
}
std::unique_ptr<SizingField3> make_mesh_sizing3(const TetMesh& background) {
  return std::make_unique<Background>(background);
}

double mean_edge_length(const TetMesh& m) {
  const std::vector<EdgeKey> edges = unique_edges(m);
  double s = 0;
  for (const auto& e : edges) s += std::sqrt(dist2(m.point(e[0]), m.point(e[1])));
  return edges.empty() ? 0 : s / static_cast<double>(edges.size());
}

}  // namespace cvtmesh
