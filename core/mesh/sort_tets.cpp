#include "core/mesh/sort_tets.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <parallel/algorithm>
#include <utility>
#include <vector>

#include "core/mesh/renumber_vertices.h"

namespace cvtmesh {
namespace {

// Spreads the low 21 bits of x to every third bit.
std::uint64_t spread3(std::uint64_t x) {
  x &= 0x1fffff;
  x = (x | x << 32) & 0x1f00000000ffffULL;
  x = (x | x << 16) & 0x1f0000ff0000ffULL;
  x = (x | x << 8) & 0x100f00f00f00f00fULL;
  x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
  x = (x | x << 2) & 0x1249249249249249ULL;
  return x;
}

// The Morton code of x in the box [lo, lo + 2097151 / scale].
std::uint64_t morton(const double* x, const double* lo, const double* scale) {
  std::uint64_t code = 0;
  for (int d = 0; d < 3; ++d)
    code |= spread3(static_cast<std::uint64_t>((x[d] - lo[d]) * scale[d])) << d;
  return code;
}

void bounding_box(const TetMesh& m, double* lo, double* scale) {
  double hi[3];
  for (int d = 0; d < 3; ++d) {
    lo[d] = std::numeric_limits<double>::infinity();
    hi[d] = -lo[d];
  }
  for (int v = 0; v < m.nb_vertices(); ++v)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], m.xyz[3 * v + d]);
      hi[d] = std::max(hi[d], m.xyz[3 * v + d]);
    }
  for (int d = 0; d < 3; ++d) scale[d] = hi[d] > lo[d] ? 2097151.0 / (hi[d] - lo[d]) : 0.0;
}

}  // namespace

namespace {

// Renumbers the vertices v with selected(v) along the Morton curve, within their own ids.
template <class Selected>
void sort_vertices_spatially(TetMesh& m, Selected selected) {
  const int nv = m.nb_vertices();
  double lo[3], scale[3];
  bounding_box(m, lo, scale);
  std::vector<int> slots;
  std::vector<std::pair<std::uint64_t, int>> key;
  for (int v = 0; v < nv; ++v)
    if (selected(v)) {
      slots.push_back(v);
      key.push_back({morton(m.point(v), lo, scale), v});
    }
  std::sort(key.begin(), key.end());
  std::vector<int> new_id(nv);
  for (int v = 0; v < nv; ++v) new_id[v] = v;
  for (std::size_t i = 0; i < key.size(); ++i) new_id[key[i].second] = slots[i];
  permute_vertices(m, new_id);
}

}  // namespace

void sort_all_vertices_spatially(TetMesh& m) {
  sort_vertices_spatially(m, [](int) { return true; });
}

void sort_free_vertices_spatially(TetMesh& m) {
  sort_vertices_spatially(m, [&m](int v) { return m.vclass[v].dim == 3; });
}

void sort_tets_spatially(TetMesh& m) {
  const int nt = m.nb_tets();
  double lo[3], scale[3];
  bounding_box(m, lo, scale);
  // Keys in parallel (dead tets last: the largest code), sorted in parallel (the keys are
  // distinct: the same order whatever the threads), the arrays permuted in parallel (the
  // Lloyd iteration sorts every 4th iteration: ~2.5 s of one thread at 9M tets).
  std::vector<std::pair<std::uint64_t, int>> key(static_cast<std::size_t>(nt));
  int live = 0;
#pragma omp parallel for schedule(static, 4096) reduction(+ : live) if (nt > 4096)
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tets[4 * static_cast<std::size_t>(t)];
    if (tv[0] < 0) {
      key[t] = {std::numeric_limits<std::uint64_t>::max(), t};
      continue;
    }
    ++live;
    double c[3] = {0, 0, 0};
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k < 4; ++k) c[d] += 0.25 * m.xyz[3 * static_cast<std::size_t>(tv[k]) + d];
    key[t] = {morton(c, lo, scale), t};
  }
  __gnu_parallel::sort(key.begin(), key.end());
  key.resize(static_cast<std::size_t>(live));
  std::vector<int> new_id(static_cast<std::size_t>(nt), -1);
#pragma omp parallel for schedule(static, 4096) if (live > 4096)
  for (int i = 0; i < live; ++i) new_id[key[i].second] = i;
  const bool has_adj = m.adj.size() == m.tets.size();
  const bool has_tags = m.tet_tags.size() == static_cast<std::size_t>(nt);
  std::vector<int> tets(4 * static_cast<std::size_t>(live)), adj, region(live);
  std::vector<std::size_t> tags;
  if (has_adj) adj.resize(tets.size());
  if (has_tags) tags.resize(live);
#pragma omp parallel for schedule(static, 4096) if (live > 4096)
  for (int i = 0; i < live; ++i) {
    const int t = key[i].second;
    for (int k = 0; k < 4; ++k) {
      tets[4 * static_cast<std::size_t>(i) + k] = m.tets[4 * static_cast<std::size_t>(t) + k];
      if (has_adj) {
        const int o = m.adj[4 * static_cast<std::size_t>(t) + k];
        adj[4 * static_cast<std::size_t>(i) + k] =
            (o < 0 || new_id[o / 4] < 0) ? -1 : 4 * new_id[o / 4] + o % 4;
      }
    }
    region[i] = m.tet_region[t];
    if (has_tags) tags[i] = m.tet_tags[t];
  }
  m.tets.swap(tets);
  m.tet_region.swap(region);
  if (has_adj) m.adj.swap(adj);
  if (has_tags) m.tet_tags.swap(tags);
}

}  // namespace cvtmesh
