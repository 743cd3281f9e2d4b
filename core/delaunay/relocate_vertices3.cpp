#include "core/delaunay/relocate_vertices3.h"

#include <algorithm>

#include "core/delaunay/restore_delaunay3.h"
#include "core/geometry/predicates.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {
namespace {

bool tet_positive(const TetMesh& m, int t) {
  const int* tv = &m.tets[4 * t];
  return orient3d(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])) > 0;
}

// Every tet of v's star is positively oriented with v where it is now.
bool star_valid(const TetMesh& m, const VertexTets& star, int v) {
  for (const int* it = star.begin_of(v); it != star.end_of(v); ++it)
    if (!tet_positive(m, *it)) return false;
  return true;
}

// Moves v towards its target: the whole move, else the longest of 1/2, 1/4, 1/8 of it that keeps
// its star valid (else it stays). Returns 0 for the whole move, k for 1/2^k, -1 for none.
int move_vertex(TetMesh& m, const VertexTets& star, const std::vector<double>& target, int v) {
  double* x = &m.xyz[3 * v];
  const double from[3] = {x[0], x[1], x[2]};
  double t = 1.0;
  for (int h = 0; h < 4; ++h, t *= 0.5) {
    for (int d = 0; d < 3; ++d)
      x[d] = h == 0 ? target[3 * v + d] : from[d] + t * (target[3 * v + d] - from[d]);
    if (star_valid(m, star, v)) return h;
  }
  for (int d = 0; d < 3; ++d) x[d] = from[d];
  return -1;
}

// The first round, when (nearly) every free vertex moves. Moving all at once is valid wherever the
// tets are positive with all their vertices at the targets: those vertices jump there together
// (tested in parallel; the result does not depend on the thread count). The vertices of the other
// tets ("careful") stay, and so does every jumped vertex of a tet left non-positive next to a
// careful one (back to its old position, repeated until every tet is positive); then the careful
// vertices move one by one in vertex order, each keeping its star valid. reached[i]: move_vertex's
// code for pending[i].
void first_round_moves(TetMesh& m, const VertexTets& star, const std::vector<double>& target,
                       const std::vector<int>& pending, std::vector<int>& reached) {
  const int nv = m.nb_vertices(), nt = m.nb_tets();
  const int np = static_cast<int>(pending.size());
  std::vector<int> slot(nv, -1);  // index in pending
  for (int i = 0; i < np; ++i) slot[pending[i]] = i;
  std::vector<char> careful(np, 0);
  std::vector<char> bad(nt, 0);
#pragma omp parallel for schedule(static, 1024) if (nt > 1024)
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tets[4 * t];
    if (tv[0] < 0 || (slot[tv[0]] < 0 && slot[tv[1]] < 0 && slot[tv[2]] < 0 && slot[tv[3]] < 0))
      continue;
    bad[t] = orient3d(&target[3 * tv[0]], &target[3 * tv[1]], &target[3 * tv[2]],
                      &target[3 * tv[3]]) <= 0;
  }
  for (int t = 0; t < nt; ++t)
    if (bad[t])
      for (int k = 0; k < 4; ++k)
        if (const int i = slot[m.tets[4 * t + k]]; i >= 0) careful[i] = 1;
  std::vector<double> old(3 * static_cast<std::size_t>(np));
#pragma omp parallel for schedule(static, 1024) if (np > 1024)
  for (int i = 0; i < np; ++i) {
    double* x = &m.xyz[3 * pending[i]];
    for (int d = 0; d < 3; ++d) old[3 * i + d] = x[d];
    if (!careful[i])
      for (int d = 0; d < 3; ++d) x[d] = target[3 * pending[i] + d];
  }
  // Tets mixing jumped and careful vertices must be positive as they are.
  std::vector<int> queue;
  for (int i = 0; i < np; ++i)
    if (careful[i]) queue.push_back(pending[i]);
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const int c = queue[q];
    for (const int* it = star.begin_of(c); it != star.end_of(c); ++it) {
      if (tet_positive(m, *it)) continue;
      for (int k = 0; k < 4; ++k) {
        const int w = m.tets[4 * *it + k];
        const int i = slot[w];
        if (i < 0 || careful[i]) continue;
        careful[i] = 1;
        for (int d = 0; d < 3; ++d) m.xyz[3 * w + d] = old[3 * i + d];
        queue.push_back(w);
      }
    }
  }
  reached.assign(np, 0);
  for (int i = 0; i < np; ++i)
    if (careful[i]) reached[i] = move_vertex(m, star, target, pending[i]);
}

}  // namespace

RelocateStats relocate_vertices(TetMesh& m, const ConstrainedFaces& cf,
                                const std::vector<double>& target, int max_rounds) {
  RelocateStats st;
  std::vector<int> pending;
  for (int v = 0; v < m.nb_vertices(); ++v)
    for (int d = 0; d < 3; ++d)
      if (m.xyz[3 * v + d] != target[3 * v + d]) {
        pending.push_back(v);
        break;
      }
  bool delaunay = true;
  std::vector<int> reached;
  for (st.rounds = 1; st.rounds <= max_rounds; ++st.rounds) {
    // Later rounds move few vertices: only their stars are needed.
    const VertexTets star = st.rounds == 1 ? vertex_tets(m) : vertex_tets_of(m, pending);
    if (st.rounds == 1) {
      first_round_moves(m, star, target, pending, reached);
    } else {
      reached.resize(pending.size());
      for (std::size_t i = 0; i < pending.size(); ++i)
        reached[i] = move_vertex(m, star, target, pending[i]);
    }
    std::vector<int> left, moved;
    for (std::size_t i = 0; i < pending.size(); ++i) {
      if (reached[i] >= 0) moved.push_back(pending[i]);
      if (reached[i] != 0) left.push_back(pending[i]);
    }
    // The first round moved (nearly) everything: test every face (every tet is positive: each
    // move above kept it so); later rounds only the stars of what they moved.
    RestoreDelaunayStats rs;
    if (st.rounds == 1) {
      rs = restore_delaunay_by_flips(m, cf, /*check_orientation=*/false);
    } else {
      std::vector<int> tets;
      for (int v : moved) tets.insert(tets.end(), star.begin_of(v), star.end_of(v));
      rs = restore_delaunay_in(m, cf, tets);
    }
    st.nb_flips += rs.nb_flips23 + rs.nb_flips32;
    delaunay = delaunay && rs.ok;  // faces left stuck earlier are not tested again
    st.nb_stuck += rs.nb_stuck;
    st.stuck_faces.insert(st.stuck_faces.end(), rs.stuck_faces.begin(), rs.stuck_faces.end());
    pending.swap(left);
    if (pending.empty()) break;
  }
  st.nb_pending = static_cast<int>(pending.size());
  st.ok = pending.empty() && delaunay;
  return st;
}

}  // namespace cvtmesh
