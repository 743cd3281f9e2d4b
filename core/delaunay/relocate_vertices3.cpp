#include "core/delaunay/relocate_vertices3.h"

#include <algorithm>

#include "core/delaunay/restore_delaunay3.h"
#include "core/geometry/predicates.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {
namespace {

// Every tet of v's star is positively oriented with v where it is now.
bool star_valid(const TetMesh& m, const VertexTets& star, int v) {
  for (const int* it = star.begin_of(v); it != star.end_of(v); ++it) {
    const int* tv = &m.tets[4 * *it];
    if (orient3d(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])) <= 0) return false;
  }
  return true;
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
  for (st.rounds = 1; st.rounds <= max_rounds; ++st.rounds) {
    const VertexTets star = vertex_tets(m);
    std::vector<int> left, moved;
    for (int v : pending) {
      double* x = &m.xyz[3 * v];
      const double from[3] = {x[0], x[1], x[2]};
      // The whole move, else the longest of 1/2, 1/4, 1/8 of it that keeps the star valid.
      int reached = -1;  // 0: the whole move, k: 1/2^k of it, -1: none
      double t = 1.0;
      for (int h = 0; h < 4 && reached < 0; ++h, t *= 0.5) {
        for (int d = 0; d < 3; ++d)
          x[d] = h == 0 ? target[3 * v + d] : from[d] + t * (target[3 * v + d] - from[d]);
        if (star_valid(m, star, v)) reached = h;
      }
      if (reached < 0)
        for (int d = 0; d < 3; ++d) x[d] = from[d];
      else
        moved.push_back(v);
      if (reached != 0) left.push_back(v);
    }
    // The first round moved (nearly) everything: test every face; later rounds only the stars
    // of what they moved.
    const RestoreDelaunayStats rs =
        st.rounds == 1 ? restore_delaunay_by_flips(m, cf) : restore_delaunay_around(m, cf, moved);
    st.nb_flips += rs.nb_flips23 + rs.nb_flips32;
    delaunay = delaunay && rs.ok;  // faces left stuck earlier are not tested again
    st.nb_stuck += rs.nb_stuck;
    pending.swap(left);
    if (pending.empty()) break;
  }
  st.nb_pending = static_cast<int>(pending.size());
  st.ok = pending.empty() && delaunay;
  return st;
}

}  // namespace cvtmesh
