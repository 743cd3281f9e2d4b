// The CAD reference geometry through Gmsh: surface vertices of a meshed OpenCASCADE ball move on
// the exact sphere (to 1e-12), curve vertices (the seam) on its curve, the points never.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/boundary/boundary_lloyd.h"
#include "core/boundary/smooth_boundary_maxmin.h"
#include "core/cvt/sizing_field3.h"
#include "core/io/gmsh_cad_boundary.h"
#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/mesh/check_mesh.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

TEST(CadBoundary, SurfaceVerticesOfABallStayOnTheSphereTo1e12) {
  const std::string dir = testing::temp_dir();
  const std::string geo = dir + "/ball.geo";
  {
    std::ofstream f(geo);
    f << "SetFactory(\"OpenCASCADE\");\nSphere(1) = {0.1, 0.2, 0.3, 1};\n"
         "Mesh.MeshSizeMax = 0.35;\nMesh.MeshSizeMin = 0.35;\n";
  }
  GmshSession session;
  gmsh::open(geo);
  gmsh::model::mesh::generate(3);
  MeshData d = mesh_from_gmsh(3, "ball");
  TetMesh& m = d.tet;
  ASSERT_TRUE(gmsh_model_has_cad(m));
  const TetMesh start = m;
  const BoundaryModel b = make_gmsh_cad_boundary(m);
  EXPECT_GT(b.nb_surface_vertices, 0);
  EXPECT_GT(b.nb_curve_vertices, 0);  // the seam
  EXPECT_EQ(std::string(b.geometry->kind()), "cad");
  auto radius_error = [](const double* p) {
    return std::fabs(std::sqrt((p[0] - 0.1) * (p[0] - 0.1) + (p[1] - 0.2) * (p[1] - 0.2) +
                               (p[2] - 0.3) * (p[2] - 0.3)) -
                     1);
  };
  const auto sizing = make_uniform_sizing3(0.35);
  BoundaryLloydOptions lo;
  lo.max_rounds = 3;
  lo.hausdorff = 0.05;
  const BoundaryLloydStats ls = boundary_lloyd(m, b, *sizing, lo);
  BoundaryMaxMinOptions mo;
  mo.hausdorff = 0.05;
  mo.passes = 1;
  smooth_boundary_maxmin(m, b, mo);
  ASSERT_TRUE(check_mesh(m).ok);
  int moved_surface = 0, moved_curve = 0;
  for (int v = 0; v < start.nb_vertices(); ++v) {
    const double *p = m.point(v), *p0 = start.point(v);
    const bool moved = p[0] != p0[0] || p[1] != p0[1] || p[2] != p0[2];
    if (!moved) continue;
    const VertexClass c = start.vclass[v];
    ASSERT_NE(c.dim, 0) << "a CAD point moved";
    if (c.dim == 2) {
      ++moved_surface;
      EXPECT_LE(radius_error(p), 1e-12) << v;
    }
    if (c.dim == 1) {
      ++moved_curve;
      EXPECT_LE(radius_error(p), 1e-12) << v;
    }
  }
  EXPECT_GT(ls.nb_moved, 0) << "refused " << ls.nb_refused << " undone " << ls.nb_undone;
  // The projection of a vertex already on the sphere is itself.
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (b.role_of(v).role == BoundaryRole::kSurface) {
      double q[3];
      ASSERT_TRUE(b.geometry->closest_on_surface(b.role_of(v).entity, m.point(v), q));
      for (int d = 0; d < 3; ++d) EXPECT_NEAR(q[d], m.point(v)[d], 1e-12);
      break;
    }
  EXPECT_GT(moved_surface, 0);
  (void)moved_curve;
}

}  // namespace
}  // namespace cvtmesh
