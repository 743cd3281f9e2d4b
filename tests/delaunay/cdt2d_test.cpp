// Constrained Delaunay triangulation in 2D: degenerate inputs, segments, holes, re-meshing.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "core/delaunay/cdt2d.h"
#include "core/delaunay/cdt2d_remesh.h"
#include "core/geometry/predicates.h"
#include "core/geometry/tet_geometry.h"
#include "core/io/read_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/face_key.h"
#include "core/swap/flip2d_delaunay.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// The triangles inside the segments as a TriMesh2 (for check_mesh and the Delaunay test).
TriMesh2 inside_mesh(const Cdt2dResult& r) {
  TriMesh2 m;
  m.xy.assign(r.xy.begin(), r.xy.begin() + 2 * r.nb_points);
  m.vclass.assign(r.nb_points, VertexClass{2, 1});
  for (std::size_t t = 0; t < r.component.size(); ++t)
    if (r.component[t] >= 0) {
      m.tris.insert(m.tris.end(), {r.tris[3 * t], r.tris[3 * t + 1], r.tris[3 * t + 2]});
      m.tri_region.push_back(1);
    }
  m.edges = r.segments;
  m.edge_curve.assign(r.segments.size() / 2, 1);
  build_adjacency2(m);
  return m;
}

int nb_not_delaunay(const TriMesh2& m) {
  std::set<EdgeKey> cons;
  for (int e = 0; e < m.nb_edges(); ++e) cons.insert(edge_key(m.edges[2 * e], m.edges[2 * e + 1]));
  int bad = 0;
  for (int t = 0; t < m.nb_tris(); ++t)
    for (int e = 0; e < 3; ++e) {
      const int* tv = &m.tris[3 * t];
      if (cons.count(edge_key(tv[(e + 1) % 3], tv[(e + 2) % 3]))) continue;
      if (!is_locally_delaunay2d(m, 3 * t + e)) ++bad;
    }
  return bad;
}

double total_area(const TriMesh2& m) {
  double a = 0;
  for (int t = 0; t < m.nb_tris(); ++t)
    a += tri_area2d(m.point(m.tris[3 * t]), m.point(m.tris[3 * t + 1]), m.point(m.tris[3 * t + 2]));
  return a;
}

// A square grid: every cell's four corners are cocircular, and the boundary points are
// collinear with the four corner-to-corner segments, which must be split at them.
TEST(Cdt2d, CocircularGridWithCollinearBoundary) {
  const int n = 6;
  std::vector<double> xy;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) xy.insert(xy.end(), {double(i), double(j)});
  auto id = [&](int i, int j) { return j * (n + 1) + i; };
  const std::vector<int> seg = {id(0, 0), id(n, 0), id(n, 0), id(n, n),
                                id(n, n), id(0, n), id(0, n), id(0, 0)};
  const Cdt2dResult r = cdt2d(xy, seg);
  EXPECT_EQ(r.nb_components, 1);
  EXPECT_EQ(r.segments.size() / 2, 4u * n);  // split at every boundary point
  const TriMesh2 m = inside_mesh(r);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(m.nb_tris(), 2 * n * n);
  EXPECT_NEAR(total_area(m), n * n, 1e-9);
  EXPECT_EQ(nb_not_delaunay(m), 0);
}

// Points on a line (plus two off it): collinear runs must not produce flat triangles.
TEST(Cdt2d, CollinearPoints) {
  std::vector<double> xy;
  for (int i = 0; i < 12; ++i) xy.insert(xy.end(), {0.5 * i, 0.25 * i});
  xy.insert(xy.end(), {2.0, 3.0, 3.0, -2.0});
  const int top = 12, bottom = 13;
  // Closed polygon: along the line (one segment through 10 intermediate points), up, back.
  const std::vector<int> seg = {0, 11, 11, top, top, 0, 0, bottom, bottom, 11};
  const Cdt2dResult r = cdt2d(xy, seg);
  EXPECT_EQ(r.segments.size() / 2, 4u + 11u);
  EXPECT_EQ(r.nb_components, 2);  // the line separates the two triangles of the polygon
  const TriMesh2 m = inside_mesh(r);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  for (int t = 0; t < m.nb_tris(); ++t)
    EXPECT_GT(
        orient2d(m.point(m.tris[3 * t]), m.point(m.tris[3 * t + 1]), m.point(m.tris[3 * t + 2])),
        0);
  EXPECT_EQ(nb_not_delaunay(m), 0);
  // Without segments: the plain Delaunay triangulation, every edge locally Delaunay.
  const Cdt2dResult d = cdt2d(xy, {});
  TriMesh2 all;
  all.xy = d.xy;
  all.tris = d.tris;
  all.adj = d.adj;
  for (int s = 0; s < 3 * all.nb_tris(); ++s) EXPECT_TRUE(is_locally_delaunay2d(all, s));
}

// Cocircular points (a regular 24-gon) plus its centre, a random cloud inside, and a segment
// that forces non-Delaunay triangles: every non-segment edge is still locally Delaunay.
TEST(Cdt2d, CocircularPolygonCloudAndInnerSegment) {
  const int k = 24;
  std::vector<double> xy;
  std::vector<int> seg;
  for (int i = 0; i < k; ++i) {
    xy.insert(xy.end(), {std::cos(2 * M_PI * i / k), std::sin(2 * M_PI * i / k)});
    seg.insert(seg.end(), {i, (i + 1) % k});
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  for (int i = 0; i < 200; ++i) xy.insert(xy.end(), {u(rng), u(rng)});
  xy.insert(xy.end(), {-0.65, 0.01, 0.66, -0.02});
  const int p = k + 200;
  seg.insert(seg.end(), {p, p + 1});
  const Cdt2dResult r = cdt2d(xy, seg);
  const TriMesh2 m = inside_mesh(r);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(nb_not_delaunay(m), 0);
  EXPECT_EQ(m.nb_tris(), 2 * (k + 202) - k - 2);  // Euler: all points used, k on the hull
}

// Random points on a coarse integer grid (many collinear and cocircular quadruples) with random
// non-crossing segments, which may pass through points: the whole triangulation is valid, every
// segment piece is an edge and every other edge is locally Delaunay.
TEST(Cdt2d, DegenerateGridFuzz) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    std::set<std::pair<int, int>> used;
    std::vector<double> xy;
    while (used.size() < 60) {
      const int x = static_cast<int>(rng() % 12), y = static_cast<int>(rng() % 12);
      if (used.insert({x, y}).second) xy.insert(xy.end(), {double(x), double(y)});
    }
    const int n = static_cast<int>(xy.size() / 2);
    auto p = [&](int i) { return &xy[2 * i]; };
    auto cross = [&](int a, int b, int c, int d) {  // proper or touching intersection
      const double o1 = orient2d(p(a), p(b), p(c)), o2 = orient2d(p(a), p(b), p(d));
      const double o3 = orient2d(p(c), p(d), p(a)), o4 = orient2d(p(c), p(d), p(b));
      if (o1 == 0 && o2 == 0) return true;  // collinear: reject (overlap possible)
      return ((o1 >= 0 && o2 <= 0) || (o1 <= 0 && o2 >= 0)) &&
             ((o3 >= 0 && o4 <= 0) || (o3 <= 0 && o4 >= 0));
    };
    std::vector<int> seg;
    for (int tries = 0; tries < 200 && seg.size() < 30; ++tries) {
      const int a = static_cast<int>(rng() % n), b = static_cast<int>(rng() % n);
      if (a == b) continue;
      bool ok = true;
      for (std::size_t s = 0; ok && s < seg.size(); s += 2) {
        const int c = seg[s], d = seg[s + 1];
        if (a == c || a == d || b == c || b == d) {
          // Sharing an endpoint is fine unless the segments overlap.
          const int o = (a == c || a == d) ? a : b, x = o == a ? b : a, y = (c == o) ? d : c;
          ok = !(orient2d(p(o), p(x), p(y)) == 0);
        } else {
          ok = !cross(a, b, c, d);
        }
      }
      if (ok) seg.insert(seg.end(), {a, b});
    }
    const Cdt2dResult r = cdt2d(xy, seg);
    TriMesh2 all;
    all.xy = r.xy;
    all.tris = r.tris;
    all.adj = r.adj;
    all.tri_region.assign(all.nb_tris(), 1);
    all.vclass.assign(all.nb_vertices(), VertexClass{2, 1});
    all.edges = {n, n + 1, n + 1, n + 2, n + 2, n};
    all.edge_curve = {1, 1, 1};
    const MeshCheck c = check_mesh(all);
    EXPECT_TRUE(c.ok) << "seed " << seed << ": " << (c.problems.empty() ? "" : c.problems[0]);
    EXPECT_EQ(all.nb_tris(), 2 * n + 1);
    std::set<EdgeKey> edges, pieces;
    for (int t = 0; t < all.nb_tris(); ++t)
      for (int e = 0; e < 3; ++e)
        edges.insert(edge_key(all.tris[3 * t + e], all.tris[3 * t + (e + 1) % 3]));
    for (std::size_t s = 0; s < r.segments.size(); s += 2) {
      const EdgeKey k = edge_key(r.segments[s], r.segments[s + 1]);
      EXPECT_TRUE(edges.count(k)) << "seed " << seed;
      pieces.insert(k);
    }
    // Every input segment is covered by collinear pieces.
    for (std::size_t s = 0; s < seg.size(); s += 2) {
      double len = 0;
      for (const EdgeKey& k : pieces)
        if (orient2d(p(seg[s]), p(seg[s + 1]), p(k[0])) == 0 &&
            orient2d(p(seg[s]), p(seg[s + 1]), p(k[1])) == 0) {
          const double* a = p(seg[s]);
          const double* b = p(seg[s + 1]);
          auto t = [&](int v) {
            return ((xy[2 * v] - a[0]) * (b[0] - a[0]) + (xy[2 * v + 1] - a[1]) * (b[1] - a[1]));
          };
          const double l2 = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
          const double t0 = t(k[0]) / l2, t1 = t(k[1]) / l2;
          if (std::min(t0, t1) >= -1e-12 && std::max(t0, t1) <= 1 + 1e-12)
            len += std::fabs(t1 - t0);
        }
      EXPECT_NEAR(len, 1.0, 1e-9) << "seed " << seed << " segment " << s / 2;
    }
    int bad = 0;
    for (int t = 0; t < all.nb_tris(); ++t)
      for (int e = 0; e < 3; ++e) {
        const int* tv = &all.tris[3 * t];
        if (pieces.count(edge_key(tv[(e + 1) % 3], tv[(e + 2) % 3]))) continue;
        if (!is_locally_delaunay2d(all, 3 * t + e)) ++bad;
      }
    EXPECT_EQ(bad, 0) << "seed " << seed;
  }
}

TEST(Cdt2d, RejectsBadInput) {
  EXPECT_THROW(cdt2d({0, 0, 1, 0, 0, 1, 1, 0}, {}), InputError);            // duplicate point
  EXPECT_THROW(cdt2d({0, 0, 1, 0, 0, 1}, {0, 5}), InputError);              // id out of range
  EXPECT_THROW(cdt2d({0, 0, 2, 2, 2, 0, 0, 2}, {0, 1, 2, 3}), InputError);  // crossing
}

// Re-meshing a Gmsh mesh with a hole keeps the hole, the boundary and the vertex count, and
// gives a valid, Delaunay mesh of the same area.
TEST(Cdt2dRemesh, WasherKeepsHoleAndBoundary) {
  MeshData d = read_mesh(testing::geo_path("washer.geo"), {.dim = 2});
  TriMesh2& m = d.tri;
  ASSERT_TRUE(check_mesh(m).ok);
  const double area = total_area(m);
  const int nt = m.nb_tris();
  cdt2d_remesh(m);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
  EXPECT_EQ(m.nb_tris(), nt);  // Euler: same vertices, same boundary, one hole
  EXPECT_NEAR(total_area(m), area, 1e-9 * area);
  EXPECT_EQ(nb_not_delaunay(m), 0);
}

// cdt2d_and_delaunay inserts the points once for both triangulations: each result is the one
// of its own call (same triangles, numbering and adjacency), on random points with segments
// that forces recovery flips and on a cocircular grid; and the Delaunay one is Delaunay.
TEST(Cdt2d, OneInsertionGivesBothCallsResults) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> xy;
    const bool grid = seed % 2 == 0;
    for (int i = 0; i < 15; ++i)
      for (int j = 0; j < 15; ++j)
        if (grid)
          xy.insert(xy.end(), {double(i), double(j)});
        else
          xy.insert(xy.end(), {u(rng), u(rng)});
    // A long segment between two far points (through many triangles: recovered by flips; on
    // the grid, split at the points on the diagonal).
    const std::vector<int> one = {0, 224};
    Cdt2dResult both_c, both_d;
    cdt2d_and_delaunay(xy, one, both_c, both_d);
    const Cdt2dResult c = cdt2d(xy, one), d = cdt2d(xy, {});
    EXPECT_EQ(both_c.tris, c.tris);
    EXPECT_EQ(both_c.adj, c.adj);
    EXPECT_EQ(both_c.component, c.component);
    EXPECT_EQ(both_c.segments, c.segments);
    EXPECT_EQ(both_d.tris, d.tris);
    EXPECT_EQ(both_d.adj, d.adj);
    TriMesh2 m;
    m.xy = d.xy;
    m.tris = d.tris;
    m.adj = d.adj;
    int bad = 0;
    for (int s = 0; s < static_cast<int>(m.tris.size()); ++s) bad += !is_locally_delaunay2d(m, s);
    EXPECT_EQ(bad, 0) << "seed " << seed;
  }
}

// cdt2d_remesh's Delaunay triangulation is cdt2d(mesh.xy, {}) of the rebuilt mesh's positions
// (the quad: every vertex is in a triangle); the washer's arc centres are in none: no
// triangulation of a subset is given as the whole set's.
TEST(Cdt2dRemesh, GivesTheDelaunayTriangulationOfThePositions) {
  MeshData d = read_mesh(testing::geo_path("quad.geo"), {.dim = 2});
  TriMesh2& m = d.tri;
  Cdt2dResult del;
  cdt2d_remesh(m, &del);
  const Cdt2dResult want = cdt2d(m.xy, {});
  ASSERT_FALSE(del.tris.empty());
  EXPECT_EQ(del.tris, want.tris);
  EXPECT_EQ(del.adj, want.adj);
  EXPECT_EQ(del.xy, want.xy);
  MeshData w = read_mesh(testing::geo_path("washer.geo"), {.dim = 2});
  del.tris = {0, 1, 2};
  cdt2d_remesh(w.tri, &del);
  EXPECT_TRUE(del.tris.empty());
}

}  // namespace
}  // namespace cvtmesh
