// Boundary optimization on a box whose whole boundary is one surface entity (like an STL box):
// the discrete geometry finds its 6 faces, 12 feature edges and 8 corners by the feature angle;
// the constrained CVT and the boundary max-min keep face vertices on their faces, edge vertices
// on their edges and corners in place, never invert a tet, never raise the CVT energy, and make
// the faces' triangles better.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include "core/boundary/boundary_lloyd.h"
#include "core/boundary/boundary_move.h"
#include "core/boundary/discrete_boundary.h"
#include "core/boundary/smooth_boundary_maxmin.h"
#include "core/boundary/verify_free_boundary.h"
#include "core/cvt/lloyd3.h"
#include "core/cvt/sizing_field3.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/verify_mesh.h"
#include "core/quality/quality.h"
#include "tests/support/box_moves.h"
#include "tests/support/thread_counts.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

constexpr int kN = 4;  // the box [0, 4]^3, lattice spacing 1

// How many coordinates of p are on the box's faces (0 or kN).
int nb_on_faces(const double* p) {
  int k = 0;
  for (int d = 0; d < 3; ++d) k += p[d] == 0 || p[d] == kN;
  return k;
}

// The box's lattice jittered within its faces and edges (test_meshes.h), deterministic.
TetMesh jittered_box(double amount) {
  return testing::jittered_box(kN, amount, 12345u);
}

double face_tri_q_min(const TetMesh& m, const TetMesh& ref, int d, double value) {
  double q = 1;
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* v = &m.tris[3 * f];
    if (ref.point(v[0])[d] == value && ref.point(v[1])[d] == value && ref.point(v[2])[d] == value)
      q = std::min(q, tri_quality(m.point(v[0]), m.point(v[1]), m.point(v[2]), 3, Measure::kQ));
  }
  return q;
}

TEST(DiscreteBoundary, AnStlBoxHasSixFacesTwelveFeatureEdgesAndEightCorners) {
  const TetMesh m = jittered_box(0.25);
  ASSERT_TRUE(check_mesh(m).ok);
  const BoundaryModel b = make_discrete_boundary(m);
  std::set<int> surfaces, curves;
  int corners = 0;
  for (int v = 0; v < m.nb_vertices(); ++v) {
    const VertexRole r = b.role_of(v);
    const int on = nb_on_faces(m.point(v));
    if (on == 3) {
      EXPECT_EQ(r.role, BoundaryRole::kFixed) << v;
      ++corners;
    } else if (on == 2) {
      EXPECT_EQ(r.role, BoundaryRole::kCurve) << v;
      curves.insert(r.entity);
    } else if (on == 1) {
      EXPECT_EQ(r.role, BoundaryRole::kSurface) << v;
      surfaces.insert(r.entity);
    } else {
      EXPECT_EQ(r.role, BoundaryRole::kInterior) << v;
    }
  }
  EXPECT_EQ(corners, 8);
  EXPECT_EQ(b.nb_fixed_vertices, 8);
  EXPECT_EQ(curves.size(), 12u);
  EXPECT_EQ(surfaces.size(), 6u);
  // The curves' edges are known exactly: a boundary edge is one iff both ends lie on one box edge
  // (12 edges of 4 segments); an edge joining vertices of two different box edges (or a corner
  // and another box edge) across a face is not, though neither end is a surface vertex.
  ASSERT_TRUE(b.curve_edges_known);
  std::set<std::pair<int, int>> curve_edges, across;
  for (int f = 0; f < m.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int x = m.tris[3 * f + k], y = m.tris[3 * f + (k + 1) % 3];
      const double *p = m.point(x), *q = m.point(y);
      int shared = 0;
      for (int d = 0; d < 3; ++d) shared += p[d] == q[d] && (p[d] == 0 || p[d] == kN);
      const std::pair<int, int> e{std::min(x, y), std::max(x, y)};
      EXPECT_EQ(b.may_be_curve_edge(x, y), shared == 2) << x << "-" << y;
      if (shared == 2) curve_edges.insert(e);
      if (shared < 2 && b.role_of(x).role != BoundaryRole::kSurface &&
          b.role_of(y).role != BoundaryRole::kSurface)
        across.insert(e);
    }
  EXPECT_EQ(curve_edges.size(), 48u);
  EXPECT_EQ(b.curve_edges.size(), 48u);
  EXPECT_GT(across.size(), 0u);  // what the conservative rule (no edge list) would refuse
  // A feature angle above 90 degrees makes the whole box one smooth patch: no curves, no corners.
  BoundaryModelOptions o;
  o.feature_angle = 95;
  EXPECT_EQ(make_discrete_boundary(m, o).nb_fixed_vertices, 0);
}

TEST(BoundaryMoves, FaceEdgeAndCornerVerticesStayOnTheirEntitiesAndTheFacesImprove) {
  TetMesh m = jittered_box(0.3);
  const TetMesh start = m;
  const BoundaryModel b = make_discrete_boundary(m);
  const auto sizing = make_uniform_sizing3(1.0);
  // The boundary max-min alone (the constrained CVT optimizes the volume's cells, not the
  // faces' triangles): every face triangle is guarded at its fan's minimum and in the objective.
  (void)sizing;
  BoundaryMaxMinOptions mo;
  mo.tri_below = 1;
  mo.tri_floor = 1;
  mo.passes = 4;
  const BoundaryMaxMinStats ms = smooth_boundary_maxmin(m, b, mo);
  EXPECT_GT(ms.nb_tried, 0);
  ASSERT_TRUE(check_mesh(m).ok);
  EXPECT_EQ(testing::nb_not_positive(m), 0);
  // The coordinates that put a vertex on faces kept to 1e-12, corners fixed, inside the box.
  const auto moved = testing::box_moves(m, start, kN);
  EXPECT_GT(moved[1], 0);  // on a face
  EXPECT_GT(moved[2], 0);  // on an edge
  // Every face's worst triangle is better.
  for (int d = 0; d < 3; ++d)
    for (double value : {0.0, double(kN)})
      EXPECT_GT(face_tri_q_min(m, start, d, value), face_tri_q_min(start, start, d, value))
          << "face " << d << "=" << value;
  // The end-of-run invariants hold: same triangles, volume unchanged (flat faces, fixed corners).
  VerifyOptions vo;
  vo.boundary_moves = true;
  vo.volume_tolerance = 1e-9;
  EXPECT_NO_THROW(verify_optimized(start, m, vo));
  FreeBoundaryTolerances ft;
  ft.hausdorff = 1e-9;
  const FreeBoundaryReport r = verify_free_boundary(start, m, b, ft);
  EXPECT_LE(r.hausdorff.value(), 1e-9);
  EXPECT_GT(r.tri_q_min_after, r.tri_q_min_before);
}

TEST(BoundaryLloyd, TheCvtEnergyNeverIncreasesWithTheBoundaryFree) {
  TetMesh m = jittered_box(0.3);
  const BoundaryModel b = make_discrete_boundary(m);
  const auto sizing = make_uniform_sizing3(1.0);
  BoundaryLloydOptions o;
  o.max_rounds = 8;
  o.tolerance = 0;
  const BoundaryLloydStats s = boundary_lloyd(m, b, *sizing, o);
  ASSERT_GE(s.energy.size(), 3u);
  for (std::size_t i = 1; i < s.energy.size(); ++i) EXPECT_LE(s.energy[i], s.energy[i - 1]) << i;
  EXPECT_LT(s.energy.back(), 0.99 * s.energy.front());
}

// The curve guard refuses the moves of vertices on the input's curves that would raise their
// star's maximum dihedral angle (at its strictest, 0 degrees: any rise): on the box's 12 edges
// some of the 1D CVT's moves do, so it refuses more than the run without it, and its result is
// as valid.
TEST(BoundaryLloyd, TheCurveGuardRefusesMovesThatRaiseTheMaximumDihedral) {
  auto run = [](double guard) {
    TetMesh m = jittered_box(0.3);
    const BoundaryModel b = make_discrete_boundary(m);
    // The edges' vertices on curves of the input's model, as a CAD model's mesh has them.
    for (int v = 0; v < m.nb_vertices(); ++v)
      if (nb_on_faces(m.point(v)) == 2) m.vclass[v].dim = 1;
    const auto sizing = make_uniform_sizing3(1.0);
    BoundaryLloydOptions o;
    o.max_rounds = 1;
    o.tolerance = 0;
    o.curve_angle_guard = guard;
    const BoundaryLloydStats st = boundary_lloyd(m, b, *sizing, o);
    EXPECT_TRUE(check_mesh(m).ok);
    return st;
  };
  const BoundaryLloydStats off = run(180), strict = run(0);
  ASSERT_EQ(off.rounds, 1);
  ASSERT_EQ(strict.rounds, 1);
  EXPECT_GT(strict.nb_refused, off.nb_refused);
  EXPECT_LT(strict.nb_moved, off.nb_moved);
}

// The pipeline skips its second Lloyd run when the constrained CVT reports the interior
// converged (interior_D below the tolerance): that D is the one the Lloyd iteration's first
// step reports on the returned mesh under the same sizing field.
TEST(BoundaryLloyd, ItsInteriorDIsTheLloydIterationsFirstD) {
  TetMesh m = testing::unoptimized_cube_sphere();
  const BoundaryModel b = make_discrete_boundary(m);
  const auto sizing =
      std::shared_ptr<const SizingField3>(make_uniform_sizing3(mean_edge_length(m)).release());
  BoundaryLloydOptions o;
  o.max_rounds = 2;
  o.hausdorff = 1e-3 * b.diagonal;
  const BoundaryLloydStats st = boundary_lloyd(m, b, *sizing, o);
  ASSERT_GT(st.interior_D, 0);
  Lloyd3Options lo;
  lo.sizing = sizing;
  lo.lloyd.max_iterations = 1;
  double D = -1;
  lloyd_optimize_3d(m, lo, [&](const LloydStep& s) { D = s.D; });
  EXPECT_NEAR(st.interior_D, D, 1e-9 * D);
}

// The boundary targets are projected in parallel, the moves made in vertex order: the same mesh,
// counts and energies for any number of threads (cube_sphere: ~1k boundary vertices, several
// chunks of the projection loop; with the volume budget and the Hausdorff check of a run).
TEST(BoundaryLloyd, SameResultForAnyNumberOfThreads) {
  const auto runs = testing::for_each_thread_count([] {
    TetMesh m = testing::unoptimized_cube_sphere();
    const BoundaryModel b = make_discrete_boundary(m);
    const auto sizing = make_uniform_sizing3(mean_edge_length(m));
    VolumeBudget budget = VolumeBudget::of(m, 0.001);
    BoundaryLloydOptions o;
    o.max_rounds = 3;
    o.hausdorff = 1e-3 * b.diagonal;
    o.volume_budget = &budget;
    const BoundaryLloydStats st = boundary_lloyd(m, b, *sizing, o);
    return std::make_pair(std::move(m), st);
  });
  EXPECT_GT(runs[0].second.nb_moved, 1000);
  for (std::size_t k = 1; k < runs.size(); ++k) {
    SCOPED_TRACE("run " + std::to_string(k));
    const auto& [m, st] = runs[k];
    EXPECT_EQ(m.xyz, runs[0].first.xyz);
    EXPECT_EQ(m.tets, runs[0].first.tets);
    EXPECT_EQ(st.nb_moved, runs[0].second.nb_moved);
    EXPECT_EQ(st.nb_refused, runs[0].second.nb_refused);
    EXPECT_EQ(st.energy, runs[0].second.energy);
  }
}

TEST(BoundaryMoves, ARefusedMoveLeavesTheMeshUnchanged) {
  TetMesh m = jittered_box(0.3);
  const BoundaryModel b = make_discrete_boundary(m);
  const VertexTets star = vertex_tets(m);
  const BoundaryFans fans = boundary_fans(m);
  int face = -1;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (b.role_of(v).role == BoundaryRole::kSurface) {
      face = v;
      break;
    }
  ASSERT_GE(face, 0);
  // Far across the face: some tet of the star inverts.
  double far[3];
  for (int d = 0; d < 3; ++d) far[d] = m.point(face)[d];
  for (int d = 0; d < 3; ++d)
    if (far[d] != 0 && far[d] != kN) far[d] += 1.5;
  const PlannedBoundaryMove p = plan_boundary_move(m, b, star, fans, face, far, 1e300);
  EXPECT_EQ(p.status, BoundaryMoveStatus::kInverted);
  // A corner is not movable.
  EXPECT_EQ(plan_boundary_move(m, b, star, fans, 0, far, 1e300).status,
            BoundaryMoveStatus::kNotMovable);
  // On a flat face a tangential move stays on the reference: accepted with a 1e-12 tolerance.
  double near[3];
  for (int d = 0; d < 3; ++d) near[d] = m.point(face)[d];
  for (int d = 0; d < 3; ++d)
    if (near[d] != 0 && near[d] != kN) near[d] += 0.01;
  EXPECT_EQ(plan_boundary_move(m, b, star, fans, face, near, 1e-12).status,
            BoundaryMoveStatus::kOk);
}

}  // namespace
}  // namespace cvtmesh
