// Helpers shared by the swap, smoothing and combined-optimization tests: hand-built meshes and
// the invariants they check.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/io/read_mesh.h"
#include "core/mesh/build_adjacency.h"
#include "core/mesh/face_key.h"
#include "core/mesh/tet_mesh.h"
#include "core/quality/quality_stats.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh::testing {

// make_tet_mesh(points, tets, interior) is in tests/support/test_meshes.h.

// The n tets around the vertical edge p = 0 (0,0,-h), q = 1 (0,0,h), ring r_i = 2+i on the unit
// circle at height z (a regular n-gon).
inline TetMesh ring_mesh(int n, double h = 1.0, double z = 0.0) {
  std::vector<std::array<double, 3>> pts = {{0, 0, -h}, {0, 0, h}};
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n;
    pts.push_back({std::cos(a), std::sin(a), z});
  }
  std::vector<std::array<int, 4>> tets;
  for (int i = 0; i < n; ++i) tets.push_back({0, 1, 2 + i, 2 + (i + 1) % n});
  return make_tet_mesh(pts, tets);
}

// Live tets as sorted vertex quadruples.
inline std::set<std::array<int, 4>> tet_vertex_sets(const TetMesh& m) {
  std::set<std::array<int, 4>> s;
  for (int t = 0; t < m.nb_tets(); ++t) {
    if (m.tets[4 * t] < 0) continue;
    std::array<int, 4> k{m.tets[4 * t], m.tets[4 * t + 1], m.tets[4 * t + 2], m.tets[4 * t + 3]};
    std::sort(k.begin(), k.end());
    s.insert(k);
  }
  return s;
}

// Faces of the tet complex with no tet behind them, as sorted triples (needs adj).
inline std::set<FaceKey> boundary_faces(const TetMesh& m) {
  std::set<FaceKey> s;
  for (int t = 0; t < m.nb_tets(); ++t) {
    if (m.tets[4 * t] < 0) continue;
    for (int f = 0; f < 4; ++f)
      if (m.adj[4 * t + f] < 0)
        s.insert(face_key(m.tets[4 * t + kTetFace[f][0]], m.tets[4 * t + kTetFace[f][1]],
                          m.tets[4 * t + kTetFace[f][2]]));
  }
  return s;
}

// The constrained triangles as sorted triples.
inline std::set<FaceKey> constrained_triples(const TetMesh& m) {
  std::set<FaceKey> s;
  for (int f = 0; f < m.nb_tris(); ++f)
    s.insert(face_key(m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]));
  return s;
}

// Sum of the signed volumes of the live tets (of one region if region != 0).
inline double total_volume(const TetMesh& m, int region = 0) {
  double v = 0;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* tv = &m.tets[4 * t];
    if (tv[0] < 0 || (region != 0 && m.tet_region[t] != region)) continue;
    v += tet_volume(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3]));
  }
  return v;
}

// Number of live tets that are not positively oriented by the exact predicate (flat or inverted).
// The smallest quality of the mesh in `measure`.
inline double global_min_quality(const TetMesh& m, Measure measure) {
  const auto q = element_qualities(m, measure);
  return *std::min_element(q.begin(), q.end());
}

inline int nb_not_positive(const TetMesh& m) {
  int n = 0;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] >= 0 && !(orient3d(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])) > 0))
      ++n;
  }
  return n;
}

// Local index of the face of tet t opposite vertex v (-1 if v is not in t).
inline int face_opposite(const TetMesh& m, int t, int v) {
  for (int k = 0; k < 4; ++k)
    if (m.tets[4 * t + k] == v) return k;
  return -1;
}

// Local index of the edge (a,b) of tet t (-1 if not an edge of t).
inline int local_edge(const TetMesh& m, int t, int a, int b) {
  for (int e = 0; e < 6; ++e) {
    const int x = m.tets[4 * t + kTetEdge[e][0]], y = m.tets[4 * t + kTetEdge[e][1]];
    if ((x == a && y == b) || (x == b && y == a)) return e;
  }
  return -1;
}

// The cube minus a ball as Gmsh meshes it without its optimizer (an average-quality Delaunay
// mesh with slivers: the paper's "Init"), read once per test process.
inline const TetMesh& unoptimized_cube_sphere(bool two_regions = false) {
  auto load = [](bool two) {
    ReadOptions ro;
    ro.gmsh_optimize = false;
    if (two) ro.set_numbers = {{"two_regions", 1}};
    TetMesh m = read_mesh(geo_path("cube_sphere.geo"), ro).tet;
    if (m.adj.size() != m.tets.size()) build_adjacency(m);
    return m;
  };
  static const TetMesh one = load(false);
  if (!two_regions) return one;
  static const TetMesh two = load(true);
  return two;
}

}  // namespace cvtmesh::testing
