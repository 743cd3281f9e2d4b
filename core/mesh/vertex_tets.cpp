#include "core/mesh/vertex_tets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/geometry/vec3.h"

namespace cvtmesh {
namespace {

// Below this many tet slots the stars are built in one pass (the threads' arrays of #V counts
// would cost more than they save).
constexpr int kParallelStarTets = 200000;

// The stars of the vertices v with wanted(v), by counting sort over the live tets. Large meshes
// in parallel: each thread counts and then places the tets of one contiguous block of tet ids,
// its places within each vertex's star after those of the blocks before it -- the same arrays as
// one pass in tet order, for any number of threads (this runs once per Lloyd iteration and per
// smoothing pass).
template <class Wanted>
void build_stars(const TetMesh& mesh, Wanted wanted, VertexTets& vt) {
  const int nv = mesh.nb_vertices(), nt = mesh.nb_tets();
  vt.offset.assign(static_cast<std::size_t>(nv) + 1, 0);
#ifdef _OPENMP
  const int nb_blocks = nt >= kParallelStarTets ? std::min(omp_get_max_threads(), 8) : 1;
#else
  const int nb_blocks = 1;
#endif
  // count[b][v]: the tets of block b around v, then where block b's first one goes.
  std::vector<std::vector<int>> count(static_cast<std::size_t>(nb_blocks));
  auto block_begin = [&](int b) {
    return static_cast<int>(static_cast<long long>(nt) * b / nb_blocks);
  };
#pragma omp parallel for schedule(static, 1) num_threads(nb_blocks) if (nb_blocks > 1)
  for (int b = 0; b < nb_blocks; ++b) {
    std::vector<int>& c = count[b];
    c.assign(static_cast<std::size_t>(nv), 0);
    for (int t = block_begin(b); t < block_begin(b + 1); ++t) {
      const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
      if (tv[0] < 0) continue;
      for (int k = 0; k < 4; ++k)
        if (wanted(tv[k])) ++c[tv[k]];
    }
  }
  for (int v = 0; v < nv; ++v) {
    int at = vt.offset[v];
    for (int b = 0; b < nb_blocks; ++b) {
      const int n = count[b][v];
      count[b][v] = at;
      at += n;
    }
    vt.offset[v + 1] = at;
  }
  vt.tets.resize(static_cast<std::size_t>(vt.offset[nv]));
#pragma omp parallel for schedule(static, 1) num_threads(nb_blocks) if (nb_blocks > 1)
  for (int b = 0; b < nb_blocks; ++b) {
    std::vector<int>& fill = count[b];
    for (int t = block_begin(b); t < block_begin(b + 1); ++t) {
      const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
      if (tv[0] < 0) continue;
      for (int k = 0; k < 4; ++k)
        if (wanted(tv[k])) vt.tets[fill[tv[k]]++] = t;
    }
  }
}

}  // namespace

VertexTets vertex_tets(const TetMesh& mesh) {
  VertexTets vt;
  vertex_tets(mesh, vt);
  return vt;
}

void vertex_tets(const TetMesh& mesh, VertexTets& out) {
  build_stars(
      mesh, [](int) { return true; }, out);
}

VertexTets vertex_tets_of(const TetMesh& mesh, const std::vector<int>& vertices) {
  const int nv = mesh.nb_vertices(), nt = mesh.nb_tets();
  std::vector<char> wanted(nv, 0);
  for (int v : vertices) wanted[v] = 1;
  // One pass over the tets (fixed blocks in parallel) lists the (vertex, tet) corners of the
  // wanted vertices, block after block: in tet order for any number of threads. Only those are
  // then placed (build_stars counts and places over every tet twice, with a count per vertex
  // and thread: ~6 ms at 1M tets for each of the Lloyd re-insertion's later rounds, which move a
  // few hundred vertices).
  constexpr int kBlock = 1 << 16;
  const int nb = (nt + kBlock - 1) / kBlock;
  std::vector<std::vector<std::pair<int, int>>> corners(static_cast<std::size_t>(nb));
#pragma omp parallel for schedule(static, 1) if (nb > 1)
  for (int b = 0; b < nb; ++b) {
    const int end = std::min(nt, (b + 1) * kBlock);
    for (int t = b * kBlock; t < end; ++t) {
      const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
      if (tv[0] < 0) continue;
      for (int k = 0; k < 4; ++k)
        if (wanted[tv[k]]) corners[b].push_back({tv[k], t});
    }
  }
  VertexTets vt;
  vt.offset.assign(static_cast<std::size_t>(nv) + 1, 0);
  for (const auto& block : corners)
    for (const auto& [v, t] : block) ++vt.offset[v + 1];
  for (int v = 0; v < nv; ++v) vt.offset[v + 1] += vt.offset[v];
  vt.tets.resize(static_cast<std::size_t>(vt.offset[nv]));
  std::vector<int> fill(vt.offset.begin(), vt.offset.end() - 1);
  for (const auto& block : corners)
    for (const auto& [v, t] : block) vt.tets[fill[v]++] = t;
  return vt;
}

double shortest_star_edge(const TetMesh& mesh, const int* b, const int* e, int v) {
  double lmin = std::numeric_limits<double>::infinity();
  const double* P = mesh.point(v);
  for (const int* s = b; s != e; ++s)
    for (int j = 0; j < 4; ++j) {
      const int w = mesh.tets[4 * static_cast<std::size_t>(*s) + j];
      if (w != v) lmin = std::min(lmin, std::sqrt(dist2(P, mesh.point(w))));
    }
  return lmin;
}

}  // namespace cvtmesh
