// Surface coarsening by boundary edge collapse (core/boundary/collapse_boundary_edges.h) on a
// box [0, 4]^3 whose faces are twice as fine as its interior (face grid 0.5, interior lattice 1):
// the faces get coarser, the mesh stays valid, the corners and the feature edges (the box's 12
// edges) are kept exactly, every face vertex stays on its face, each face keeps its topology,
// the volume is kept, no tet is inverted. Every collapse the check accepts gives a valid mesh
// (over all candidate edges, without the quality floors); a single tet (its collapse would
// change the topology) and collapses that would invert a tet are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>

#include "core/boundary/collapse_boundary_edges.h"
#include "core/boundary/discrete_boundary.h"
#include "core/geometry/predicates.h"
#include "core/mesh/build_adjacency.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/optimize.h"
#include "core/pipeline/verify_mesh.h"
#include "core/util/error.h"
#include "core/swap/compact_tets.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

constexpr int kN = 4;

// The interior lattice (spacing 1, jittered) and each face's grid of spacing 0.5 (jittered in
// the face's plane, the box's edges and corners exact), deterministic; their Delaunay
// tetrahedralization.
TetMesh fine_faced_box() {
  std::vector<double> xyz;
  unsigned state = 4242;
  auto rnd = [&] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / double(1 << 24) * 2 - 1;
  };
  for (int i = 1; i < kN; ++i)
    for (int j = 1; j < kN; ++j)
      for (int k = 1; k < kN; ++k) {
        const double p[3] = {i + 0.15 * rnd(), j + 0.15 * rnd(), k + 0.15 * rnd()};
        xyz.insert(xyz.end(), p, p + 3);
      }
  std::set<std::array<long, 3>> seen;
  const int n = 2 * kN;  // face grid: spacing 0.5
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const int g[3] = {i, j, k};
        int on = 0;
        for (int d = 0; d < 3; ++d) on += g[d] == 0 || g[d] == n;
        if (on == 0) continue;
        double p[3];
        for (int d = 0; d < 3; ++d) {
          p[d] = 0.5 * g[d];
          const bool fixed = g[d] == 0 || g[d] == n;
          if (!fixed && on == 1) p[d] += 0.1 * rnd();  // inside a face: jitter in its plane
        }
        xyz.insert(xyz.end(), p, p + 3);
      }
  return testing::delaunay_of_points(xyz);
}

double mean_boundary_edge(const TetMesh& m) {
  std::set<std::pair<int, int>> edges;
  for (int f = 0; f < m.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.tris[3 * f + k], b = m.tris[3 * f + (k + 1) % 3];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  double s = 0;
  for (const auto& [a, b] : edges) s += std::sqrt(dist2(m.point(a), m.point(b)));
  return s / static_cast<double>(edges.size());
}

// Per box face (by the triangles' plane): V - E + F and the number of triangles; every edge of a
// face on one or two of its triangles.
std::map<int, std::pair<int, int>> faces_topology(const TetMesh& m) {
  std::map<int, std::vector<int>> per_face;
  for (int f = 0; f < m.nb_tris(); ++f) {
    int face = -1;
    for (int d = 0; d < 3 && face < 0; ++d)
      for (double c : {0.0, double(kN)}) {
        bool all = true;
        for (int k = 0; k < 3; ++k) all &= m.point(m.tris[3 * f + k])[d] == c;
        if (all) face = 2 * d + (c > 0);
      }
    EXPECT_GE(face, 0) << "triangle " << f << " is on no face of the box";
    per_face[face].insert(per_face[face].end(), &m.tris[3 * f], &m.tris[3 * f] + 3);
  }
  std::map<int, std::pair<int, int>> r;
  for (const auto& [face, t] : per_face) {
    std::map<std::pair<int, int>, int> edges;
    std::set<int> verts(t.begin(), t.end());
    for (std::size_t i = 0; i < t.size(); i += 3)
      for (int k = 0; k < 3; ++k) {
        const int a = t[i + k], b = t[i + (k + 1) % 3];
        ++edges[{std::min(a, b), std::max(a, b)}];
      }
    for (const auto& [e, c] : edges) EXPECT_LE(c, 2);
    const int nf = static_cast<int>(t.size() / 3);
    r[face] = {static_cast<int>(verts.size()) - static_cast<int>(edges.size()) + nf, nf};
  }
  return r;
}

TEST(CollapseBoundaryEdges, TheFacesGetCoarserAndEverythingElseIsKept) {
  TetMesh m = fine_faced_box();
  ASSERT_TRUE(check_mesh(m).ok);
  const TetMesh before = m;
  BoundaryModel b = make_discrete_boundary(m);  // 6 faces, 12 curves, 8 corners
  ASSERT_GT(b.nb_surface_vertices, 0);
  const auto topo_before = faces_topology(m);
  ASSERT_EQ(topo_before.size(), 6u);
  const double edge_before = mean_boundary_edge(m);
  VolumeBudget budget = VolumeBudget::of(m, 1e-3);
  BoundaryCollapseOptions o;
  o.hausdorff = 2e-3 * b.diagonal;
  o.volume_budget = &budget;
  const BoundaryCollapseStats st = collapse_boundary_edges(m, b, o);
  EXPECT_GT(st.nb_collapsed, 20);
  const MeshCheck c = check_mesh(m);
  ASSERT_TRUE(c.ok) << c.problems.front();
  EXPECT_LT(m.nb_tris(), before.nb_tris());
  EXPECT_GT(mean_boundary_edge(m), 1.15 * edge_before);
  // No vertex moved; every face vertex on its face plane exactly; each face the same topology
  // (a disk: V - E + F = 1), fewer triangles.
  for (int v = 0; v < m.nb_vertices(); ++v)
    for (int d = 0; d < 3; ++d) ASSERT_EQ(m.point(v)[d], before.point(v)[d]);
  const auto topo_after = faces_topology(m);
  ASSERT_EQ(topo_after.size(), 6u);
  for (const auto& [face, t] : topo_after) {
    EXPECT_EQ(t.first, topo_before.at(face).first) << "face " << face;
    EXPECT_LT(t.second, topo_before.at(face).second) << "face " << face;
  }
  // Corners and curve vertices still on the boundary, the box's edges still edges of triangles.
  std::set<int> on_tris(m.tris.begin(), m.tris.end());
  std::set<std::pair<int, int>> tri_edges;
  for (int f = 0; f < m.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int x = m.tris[3 * f + k], y = m.tris[3 * f + (k + 1) % 3];
      tri_edges.insert({std::min(x, y), std::max(x, y)});
    }
  int nb_corners = 0;
  for (int v = 0; v < before.nb_vertices(); ++v) {
    const BoundaryRole r = make_discrete_boundary(before).role_of(v).role;
    if (r == BoundaryRole::kFixed || r == BoundaryRole::kCurve) {
      EXPECT_TRUE(on_tris.count(v)) << "curve or corner vertex " << v << " removed";
      nb_corners += r == BoundaryRole::kFixed;
    }
  }
  EXPECT_EQ(nb_corners, 8);
  ASSERT_TRUE(b.curve_edges_known);
  for (const auto& e : b.curve_edges) EXPECT_TRUE(tri_edges.count({e[0], e[1]}));
  // Removed vertices: in no element, fixed in the model.
  std::vector<char> used(m.nb_vertices(), 0);
  for (int x : m.tets) used[x] = 1;
  int removed = 0;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (!used[v]) {
      ++removed;
      EXPECT_EQ(b.role_of(v).role, BoundaryRole::kFixed);
    }
  EXPECT_EQ(removed, st.nb_collapsed);
  // Volume: flat faces, so the collapses keep it (to rounding); within the budget anyway.
  const auto vb = region_volumes(before), va = region_volumes(m);
  ASSERT_EQ(va.size(), 1u);
  EXPECT_NEAR(va[0].second, vb[0].second, 1e-9 * vb[0].second);
  EXPECT_LE(std::fabs(budget.change[0]), 1e-3 * budget.volume[0]);
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* w = &m.tets[4 * t];
    ASSERT_GT(orient3d(m.point(w[0]), m.point(w[1]), m.point(w[2]), m.point(w[3])), 0);
  }
}

TEST(CollapseBoundaryEdges, EveryAcceptedCollapseIsValidAndSomeAreRefused) {
  const TetMesh m0 = fine_faced_box();
  const BoundaryModel b0 = make_discrete_boundary(m0);
  const VertexTets star = vertex_tets(m0);
  const BoundaryFans fans = boundary_fans(m0);
  const std::vector<double> spacing = interior_spacing(m0, star);
  BoundaryCollapseOptions o;  // no floors: only validity decides
  o.q_floor = 0;
  o.angle_floor = 0;
  o.tri_floor = 0;
  o.flat_angle = 180;
  o.long_fraction = 1e300;
  std::map<CollapseCheck, int> count;
  int nb_applied = 0;
  for (int v = 0; v < m0.nb_vertices(); ++v) {
    if (b0.role_of(v).role != BoundaryRole::kSurface) continue;
    std::set<int> nbrs;
    for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f)
      for (int k = 0; k < 3; ++k) nbrs.insert(m0.tris[3 * *f + k]);
    nbrs.erase(v);
    for (int w : nbrs) {
      CollapsePlan plan;
      const CollapseCheck s = plan_boundary_collapse(m0, b0, star, fans, spacing, v, w, o, plan);
      ++count[s];
      if (s != CollapseCheck::kOk || ++nb_applied > 80) continue;  // 80 applied: enough
      TetMesh m = m0;
      BoundaryModel b = b0;
      apply_boundary_collapse(m, b, plan, nullptr);
      compact_boundary_triangles(m);
      m.adj.clear();
      compact_tets(m);
      build_adjacency(m);
      const MeshCheck c = check_mesh(m);
      ASSERT_TRUE(c.ok) << v << " onto " << w << ": " << c.problems.front();
      ASSERT_EQ(m.nb_tris(), m0.nb_tris() - 2);
    }
  }
  EXPECT_GT(count[CollapseCheck::kOk], 50);
  EXPECT_GT(count[CollapseCheck::kInverted], 0);
}

TEST(CollapseBoundaryEdges, ASingleTetIsRefusedByTheLinkCondition) {
  TetMesh m = testing::make_tet_mesh({{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}},
                                     {{{0, 1, 2, 3}}});
  BoundaryModelOptions bo;
  bo.feature_angle = 179;  // one smooth patch: every vertex a surface vertex
  BoundaryModel b = make_discrete_boundary(m, bo);
  ASSERT_EQ(b.nb_surface_vertices, 4);
  const VertexTets star = vertex_tets(m);
  const BoundaryFans fans = boundary_fans(m);
  const std::vector<double> spacing(4, 10.0);
  BoundaryCollapseOptions o;
  o.q_floor = 0;
  for (int v = 0; v < 4; ++v)
    for (int w = 0; w < 4; ++w) {
      if (v == w) continue;
      CollapsePlan plan;
      EXPECT_EQ(plan_boundary_collapse(m, b, star, fans, spacing, v, w, o, plan),
                CollapseCheck::kLink);
    }
  const TetMesh before = m;
  BoundaryCollapseOptions all;
  all.short_fraction = 1e9;
  EXPECT_EQ(collapse_boundary_edges(m, b, all).nb_collapsed, 0);
  EXPECT_EQ(m.tets, before.tets);
}

// verify_optimized accepts the coarsened box only when told that the boundary may lose vertices
// (a free-boundary run with collapses), and still refuses a surface whose topology changed.
TEST(CollapseBoundaryEdges, VerifyAcceptsCollapsesOnlyWhenToldAndKeepsTheTopologyCheck) {
  const TetMesh before = fine_faced_box();
  TetMesh m = before;
  BoundaryModel b = make_discrete_boundary(m);
  ASSERT_GT(collapse_boundary_edges(m, b).nb_collapsed, 0);
  VerifyOptions vo;
  vo.boundary_moves = true;
  vo.volume_tolerance = 1e-9;
  EXPECT_THROW(verify_optimized(before, m, vo), InvariantError);
  vo.boundary_collapses = true;
  EXPECT_NO_THROW(verify_optimized(before, m, vo));
  // One box face's triangles relabelled as two surfaces: each now has boundary edges it did not.
  TetMesh split = m;
  const int s0 = split.tri_surface[0];
  for (int f = 0, k = 0; f < split.nb_tris(); ++f)
    if (split.tri_surface[f] == s0 && (k++ % 2)) split.tri_surface[f] = 777;
  EXPECT_THROW(verify_optimized(before, split, vo), InvariantError);
}

// Through optimize(): the default (free boundary) removes surface vertices of the fine-faced box
// and drops them from the result (no orphan node), an orphan node of the input is kept, the
// result is valid; with coarsen_surface = 0 or fix_boundary no vertex is removed.
TEST(CollapseBoundaryEdges, OptimizeDropsTheRemovedVerticesAndKeepsTheInputsOrphans) {
  MeshData input;
  input.dim = 3;
  input.tet = fine_faced_box();
  // An orphan node (a vertex of no element), far from the box.
  input.tet.xyz.insert(input.tet.xyz.end(), {10, 10, 10});
  input.tet.vclass.push_back(input.tet.vclass.back());
  const int n0 = input.tet.nb_vertices();
  auto used = [](const TetMesh& m) {
    std::vector<char> u(m.nb_vertices(), 0);
    for (int v : m.tets) u[v] = 1;
    int n = 0;
    for (char c : u) n += c;
    return n;
  };
  OptimizeOptions o;
  o.max_iterations = 10;
  o.auto_refine = false;  // no interior vertex added: the count is the coarsening's alone
  MeshData free = input;
  const OptimizeResult r = optimize(free, o);
  ASSERT_TRUE(r.boundary_free) << (r.notes.empty() ? "" : r.notes.front());
  EXPECT_GT(r.nb_boundary_removed, 0);
  EXPECT_EQ(free.tet.nb_vertices(), n0 - r.nb_boundary_removed);
  EXPECT_EQ(used(free.tet), free.tet.nb_vertices() - 1);  // only the input's orphan is unused
  const double* p = free.tet.point(free.tet.nb_vertices() - 1);
  EXPECT_EQ(p[0], 10);
  EXPECT_EQ(p[2], 10);
  const MeshCheck c = check_mesh(free.tet);
  ASSERT_TRUE(c.ok) << c.problems.front();
  for (const bool fixed : {false, true}) {
    MeshData same = input;
    OptimizeOptions oo = o;
    oo.coarsen_surface = fixed ? 0.7 : 0;
    oo.fix_boundary = fixed;
    const OptimizeResult rr = optimize(same, oo);
    EXPECT_EQ(rr.nb_boundary_removed, 0);
    EXPECT_EQ(same.tet.nb_vertices(), n0);
  }
}

}  // namespace
}  // namespace cvtmesh
