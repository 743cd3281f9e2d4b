// Delaunay3 (TetGen behind core/delaunay/) on degenerate point sets: cospherical lattice points,
// the same moved by 1e-14, and points exactly on hull faces and edges. The result keeps every
// constrained triangle, adds no point, has no flat or inverted tet (exact orient3d), keeps the
// volume, and is locally Delaunay across every unconstrained face (exact insphere).
#include "core/delaunay/delaunay3.h"

#include <gtest/gtest.h>

#include <string>

#include "core/mesh/check_mesh.h"
#include "core/swap/constrained_faces.h"
#include "tests/swap/swap_test_util.h"

namespace cvtmesh {
namespace {

using testing::constrained_triples;
using testing::cube_lattice;
using testing::nb_not_positive;
using testing::total_volume;

// Faces shared by two tets, not constrained, whose opposite vertex in the neighbour lies strictly
// inside the circumsphere of the tet.
int nb_non_delaunay_faces(const TetMesh& m) {
  const ConstrainedFaces cf = constrained_faces(m);
  int n = 0;
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      const int o = m.adj[4 * t + f];
      if (o < 0) continue;
      const int* v = &m.tets[4 * t];
      if (cf.count(face_key(v[kTetFace[f][0]], v[kTetFace[f][1]], v[kTetFace[f][2]]))) continue;
      const int w = m.tets[o];  // o = 4 t' + f': the vertex of t' opposite the shared face
      if (insphere(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]), m.point(w)) > 0) ++n;
    }
  return n;
}

void expect_valid_delaunay(const std::vector<double>& points, const std::string& what) {
  SCOPED_TRACE(what);
  TetMesh m = testing::delaunay_of_points(points);
  ASSERT_TRUE(check_mesh(m).ok);
  const auto tris = constrained_triples(m);
  const double vol = total_volume(m);
  const int nv = m.nb_vertices();
  const Delaunay3Stats s = Delaunay3::create("tetgen")->retetrahedralize(m);
  EXPECT_EQ(s.nb_steiner, 0);
  EXPECT_EQ(s.nb_dropped_tets, 0);
  EXPECT_EQ(m.nb_vertices(), nv);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << c.problems.front();
  EXPECT_EQ(nb_not_positive(m), 0);
  EXPECT_EQ(constrained_triples(m), tris);
  EXPECT_NEAR(total_volume(m), vol, 1e-12 * vol);
  EXPECT_EQ(nb_non_delaunay_faces(m), 0);
}

TEST(Delaunay3Degenerate, CosphericalCubeLattice) {
  expect_valid_delaunay(cube_lattice(4), "lattice 5^3");
}

TEST(Delaunay3Degenerate, CubeLatticeWithInteriorPointsMovedBy1e14) {
  expect_valid_delaunay(cube_lattice(4, 1e-14), "lattice 5^3 jittered 1e-14");
}

TEST(Delaunay3Degenerate, PointsExactlyOnHullFacesAndEdges) {
  const std::vector<double> p = testing::cube_lattice_with_hull_points();
  expect_valid_delaunay(p, "points on the hull");
}

}  // namespace
}  // namespace cvtmesh
