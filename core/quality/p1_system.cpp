#include "core/quality/p1_system.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "core/quality/p1_gradients.h"

namespace cvtmesh {
namespace {

// Element stiffness of a simplex of dimension D (D+1 vertices of D coordinates at pts[i]):
// ke[i][j] = |volume| grad phi_i . grad phi_j; returns |volume| (0 for a flat element).
template <int D>
double element_stiffness(const double* const* pts, double ke[D + 1][D + 1]);

template <>
double element_stiffness<3>(const double* const* p, double ke[4][4]) {
  double n[4][3];
  const double det = std::fabs(tet_scaled_gradients(p[0], p[1], p[2], p[3], n));
  if (det == 0) return 0;
  // grad phi_i = n_i / det, volume = det / 6.
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      ke[i][j] = (n[i][0] * n[j][0] + n[i][1] * n[j][1] + n[i][2] * n[j][2]) / (6.0 * det);
  return det / 6.0;
}

template <>
double element_stiffness<2>(const double* const* p, double ke[3][3]) {
  const double e1x = p[1][0] - p[0][0], e1y = p[1][1] - p[0][1];
  const double e2x = p[2][0] - p[0][0], e2y = p[2][1] - p[0][1];
  const double n[3][2] = {{e1y - e2y, e2x - e1x}, {e2y, -e2x}, {-e1y, e1x}};
  const double det = std::fabs(e1x * e2y - e1y * e2x);
  if (det == 0) return 0;
  // grad phi_i = n_i / det, area = det / 2.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) ke[i][j] = (n[i][0] * n[j][0] + n[i][1] * n[j][1]) / (2.0 * det);
  return det / 2.0;
}

// elems: #E by (D+1) vertex ids (dead: first id < 0); xyz: #V by stride coordinates.
template <int D>
P1System assemble(int nv, const std::vector<double>& xyz, int stride,
                  const std::vector<int>& elems) {
  constexpr int K = D + 1;
  const long ne = static_cast<long>(elems.size() / K);
  P1System s;
  s.n = nv;
  s.mass.assign(nv, 0.0);
  s.boundary.assign(nv, 0);
  // Sparsity pattern: every (i, j) pair of an element, sorted and unique.
  std::vector<std::uint64_t> keys;
  keys.reserve(static_cast<std::size_t>(ne) * K * K);
  for (long e = 0; e < ne; ++e) {
    const int* v = &elems[K * e];
    if (v[0] < 0) continue;
    ++s.nb_elements;
    for (int i = 0; i < K; ++i)
      for (int j = 0; j < K; ++j)
        keys.push_back((static_cast<std::uint64_t>(v[i]) << 32) | static_cast<std::uint32_t>(v[j]));
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  s.row_ptr.assign(nv + 1, 0);
  s.col.resize(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) {
    ++s.row_ptr[(keys[k] >> 32) + 1];
    s.col[k] = static_cast<int>(keys[k] & 0xffffffffu);
  }
  for (int i = 0; i < nv; ++i) s.row_ptr[i + 1] += s.row_ptr[i];
  s.val.assign(keys.size(), 0.0);
  // Values: serial accumulation in element order (the same sums whatever the thread count).
  for (long e = 0; e < ne; ++e) {
    const int* v = &elems[K * e];
    if (v[0] < 0) continue;
    const double* p[K];
    for (int i = 0; i < K; ++i) p[i] = &xyz[static_cast<std::size_t>(stride) * v[i]];
    double ke[K][K];
    const double vol = element_stiffness<D>(p, ke);
    if (vol == 0) continue;
    for (int i = 0; i < K; ++i) {
      s.mass[v[i]] += vol / K;
      const int* c0 = &s.col[s.row_ptr[v[i]]];
      const int* c1 = &s.col[0] + s.row_ptr[v[i] + 1];
      for (int j = 0; j < K; ++j) {
        const long at = std::lower_bound(c0, c1, v[j]) - &s.col[0];
        s.val[at] += ke[i][j];
      }
    }
  }
  // Boundary: the faces (D vertex ids, sorted) that belong to one live element only.
  std::vector<std::array<int, D>> faces;
  faces.reserve(static_cast<std::size_t>(s.nb_elements) * K);
  for (long e = 0; e < ne; ++e) {
    const int* v = &elems[K * e];
    if (v[0] < 0) continue;
    for (int skip = 0; skip < K; ++skip) {
      std::array<int, D> f{};
      for (int i = 0, k = 0; i < K; ++i)
        if (i != skip) f[k++] = v[i];
      std::sort(f.begin(), f.end());
      faces.push_back(f);
    }
  }
  std::sort(faces.begin(), faces.end());
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j == i + 1)
      for (int v : faces[i]) s.boundary[v] = 1;
    i = j;
  }
  return s;
}

}  // namespace

P1System p1_system(const TetMesh& mesh) {
  return assemble<3>(mesh.nb_vertices(), mesh.xyz, 3, mesh.tets);
}

P1System p1_system(const TriMesh2& mesh) {
  return assemble<2>(mesh.nb_vertices(), mesh.xy, 2, mesh.tris);
}

void p1_multiply(const P1System& s, const std::vector<double>& x, std::vector<double>& y) {
  y.resize(s.n);
#pragma omp parallel for schedule(static, 2048) if (s.n > 2048)
  for (int i = 0; i < s.n; ++i) {
    double sum = 0;
    for (long k = s.row_ptr[i]; k < s.row_ptr[i + 1]; ++k) sum += s.val[k] * x[s.col[k]];
    y[i] = sum;
  }
}

}  // namespace cvtmesh
