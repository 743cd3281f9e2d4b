// The per-region never-worse (restore_worse_regions, and optimize() through it): where an
// optimized mesh has elements worse than the input's worst, the vertices around them go back to
// their input positions; the rest of the mesh keeps its optimized positions.
#include "core/pipeline/restore_worse_regions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/geometry/predicates.h"
#include "core/io/read_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/optimize.h"
#include "core/quality/element_shortfall.h"
#include "core/quality/worse_than.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

bool all_positive(const TetMesh& m) {
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (orient3d(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])) <= 0) return false;
  }
  return true;
}

bool all_positive(const TriMesh2& m) {
  for (int t = 0; t < m.nb_tris(); ++t) {
    const int* v = &m.tris[3 * t];
    if (orient2d(m.point(v[0]), m.point(v[1]), m.point(v[2])) <= 0) return false;
  }
  return true;
}

// An n x n grid of the unit square, each cell split along its diagonal, interior vertices free.
TriMesh2 grid2(int n) {
  TriMesh2 m;
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      m.xy.insert(m.xy.end(), {double(i) / n, double(j) / n});
      const bool bi = i == 0 || i == n, bj = j == 0 || j == n;
      VertexClass c;
      c.dim = bi && bj ? 0 : bi || bj ? 1 : 2;
      m.vclass.push_back(c);
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.tris.insert(m.tris.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.tris.insert(m.tris.end(), {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      m.tri_region.insert(m.tri_region.end(), {1, 1});
    }
  build_adjacency2(m);
  return m;
}

TEST(RestoreWorseRegions, TwoDimensionsRestoresOnlyAroundTheWorseElements) {
  // The input: a grid with its interior vertices jittered (its worst triangle is worse than the
  // grid's); the "optimized" mesh: the regular grid (better everywhere), except vertex (5,5) moved
  // 0.6 of the way to (6,5), whose triangles get worse than the input's worst.
  TriMesh2 m = grid2(10);
  TriMesh2 input = m;
  int nudged = 0;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim == 2) {
      input.point(v)[0] += 0.02 * std::sin(1.0 + v);
      input.point(v)[1] += 0.02 * std::cos(2.0 + v);
      ++nudged;
    }
  ASSERT_TRUE(all_positive(input));
  const QualityStats ref = quality_stats(input, "");
  ASSERT_EQ(worse_than(quality_stats(m, ""), ref), "");
  const int bad = 5 * 11 + 5;
  m.point(bad)[0] += 0.06;
  ASSERT_TRUE(all_positive(m));
  ASSERT_NE(worse_than(quality_stats(m, ""), ref), "");
  const TriMesh2 optimized = m;
  const RestoreStats st = restore_worse_regions(m, input, ref);
  EXPECT_TRUE(all_positive(m));
  EXPECT_EQ(worse_than(quality_stats(m, ""), ref), "");
  EXPECT_GT(st.nb_short_before, 0);
  EXPECT_EQ(st.nb_short_after, 0);
  EXPECT_GT(st.nb_restored, 0);
  // Local: most vertices keep their optimized positions.
  int kept = 0;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim == 2)
      kept += m.point(v)[0] == optimized.point(v)[0] && m.point(v)[1] == optimized.point(v)[1];
  EXPECT_GT(kept, nudged / 2) << st.nb_restored << " restored";
  EXPECT_LE(st.nb_restored + st.nb_smoothed, nudged - kept);
  // The boundary never moves.
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim < 2) EXPECT_EQ(m.point(v)[0], input.point(v)[0]);
}

TEST(RestoreWorseRegions, ThreeDimensionsRestoresOnlyAroundTheWorseElements) {
  // As in 2D: the input is the body-centred lattice's tetrahedralization with its interior
  // vertices jittered, the "optimized" mesh the regular lattice with its middle vertex moved.
  TetMesh m = testing::delaunay_of_points(testing::bcc_lattice(4, 1.0));
  TetMesh input = m;
  int nudged = 0, bad = -1;
  double best = 1e30;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim == 3) {
      const double* p = m.point(v);
      const double d = std::hypot(p[0] - 2, p[1] - 2, p[2] - 2);
      if (d < best) best = d, bad = v;
      for (int k = 0; k < 3; ++k) input.point(v)[k] += 0.05 * std::sin(1.0 + 3 * v + k);
      ++nudged;
    }
  ASSERT_TRUE(all_positive(input));
  const QualityStats ref = quality_stats(input, "");
  ASSERT_EQ(worse_than(quality_stats(m, ""), ref), "");
  ASSERT_GE(bad, 0);
  ASSERT_TRUE(all_positive(m));
  // The middle vertex moved along x as far as its star stays valid (at most 0.45): its tets get
  // worse than the input's worst.
  const double x_bad = m.point(bad)[0];
  for (double a = 0.45; a > 0.01; a *= 0.8) {
    m.point(bad)[0] = x_bad + a;
    if (all_positive(m)) break;
  }
  ASSERT_TRUE(all_positive(m));
  ASSERT_NE(worse_than(quality_stats(m, ""), ref), "");
  const TetMesh optimized = m;
  const RestoreStats st = restore_worse_regions(m, input, ref);
  EXPECT_TRUE(all_positive(m));
  EXPECT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(worse_than(quality_stats(m, ""), ref), "");
  EXPECT_EQ(st.nb_short_after, 0);
  EXPECT_GT(st.nb_restored, 0);
  int kept = 0;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim == 3) {
      bool same = true;
      for (int k = 0; k < 3; ++k) same &= m.point(v)[k] == optimized.point(v)[k];
      kept += same;
    }
  EXPECT_GT(kept, nudged / 2) << st.nb_restored << " restored of " << nudged;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (m.vclass[v].dim < 3)
      for (int k = 0; k < 3; ++k) EXPECT_EQ(m.point(v)[k], input.point(v)[k]);
}

TEST(RestoreWorseRegions, ShortfallIsZeroExactlyWhenNoMeasureIsWorse) {
  QualityStats ref;
  ref.q_min = 0.5;
  ref.min_angle = 30;
  ref.max_angle = 120;
  EXPECT_EQ(element_shortfall(0.5, 30, 120, ref), 0);
  EXPECT_GT(element_shortfall(0.49, 30, 120, ref), 0);
  EXPECT_GT(element_shortfall(0.9, 29.9, 100, ref), 0);
  EXPECT_GT(element_shortfall(0.9, 40, 120.1, ref), 0);
}

// A 2D model where the CVT lowers the minimum angle of a few triangles (Gmsh's tutorial t1's
// rectangle): optimize restores them and keeps the rest of the CVT instead of the whole input.
TEST(RestoreWorseRegions, OptimizeTwoDimensionsKeepsTheCvtAwayFromTheWorseRegion) {
  const std::string path = testing::temp_dir() + "/t1like.geo";
  std::ofstream(path) << "lc = 1e-2;\nPoint(1) = {0, 0, 0, lc};\nPoint(2) = {.1, 0, 0, lc};\n"
                         "Point(3) = {.1, .3, 0, lc};\nPoint(4) = {0, .3, 0, lc};\n"
                         "Line(1) = {1, 2};\nLine(2) = {3, 2};\nLine(3) = {3, 4};\n"
                         "Line(4) = {4, 1};\nCurve Loop(1) = {4, 1, -2, 3};\n"
                         "Plane Surface(1) = {1};\n";
  MeshData d = read_mesh(path);
  ASSERT_EQ(d.dim, 2);
  const TriMesh2 input = d.tri;
  const OptimizeResult r = optimize(d, OptimizeOptions{});
  EXPECT_FALSE(r.kept_input) << (r.notes.empty() ? "" : r.notes.back());
  EXPECT_EQ(worse_than(quality_stats(d.tri, ""), r.before), "");
  EXPECT_GT(r.after.q_avg, r.before.q_avg);
  int moved = 0;
  for (int v = 0; v < input.nb_vertices(); ++v)
    moved += d.tri.point(v)[0] != input.point(v)[0] || d.tri.point(v)[1] != input.point(v)[1];
  EXPECT_GT(moved, input.nb_vertices() / 2);
}

}  // namespace
}  // namespace cvtmesh
