// Files that hold a surface mesh and no tetrahedra (gmsh -2 -save_all, a closed surface exported
// to .msh 2.2, Medit or VTK): the volumes inside are meshed by Gmsh and the surface mesh kept; an
// open surface in space is a surface mesh (no tets); formats Gmsh writes but cannot read get a
// clear error.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <string>

#include "core/io/read_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/util/error.h"
#include "tests/io/gmsh_dump.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

using testing::gmsh_dump;
using testing::GmshDump;
using testing::run;

double tet_volume(const TetMesh& m) {
  double total = 0;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const double* p[4];
    for (int k = 0; k < 4; ++k) p[k] = &m.xyz[3 * m.tets[4 * t + k]];
    double a[3], b[3], c[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = p[1][k] - p[0][k];
      b[k] = p[2][k] - p[0][k];
      c[k] = p[3][k] - p[0][k];
    }
    total += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
              a[2] * (b[0] * c[1] - b[1] * c[0])) /
             6;
  }
  return total;
}

std::string mesh_geo(const std::string& dir, const std::string& body, const std::string& flags,
                     const std::string& out) {
  const std::string geo = dir + "/model.geo";
  std::ofstream(geo) << body;
  const std::string path = dir + "/" + out;
  std::string log;
  EXPECT_EQ(run("gmsh -v 0 -2 -save_all " + flags + " " + geo + " -o " + path, &log), 0) << log;
  return path;
}

const char* kTwoBoxes =
    "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {1, 0, 0, 1, 1, 1};\n"
    "BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n"
    "Physical Volume(\"left\", 1) = {1};\nPhysical Volume(\"right\", 2) = {2};\n"
    "Physical Surface(\"faces\", 3) = {1, 2, 3};\nMesh.MeshSizeMax = 0.3;\n";

// A box with a spherical cavity: 1 - 4/3 pi 0.3^3.
const char* kBoxWithCavity =
    "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\nSphere(2) = {0.5, 0.5, 0.5, "
    "0.3};\n"
    "BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }\nMesh.MeshSizeMax = 0.15;\n";
const double kCavityVolume = 1 - 4.0 / 3.0 * M_PI * 0.027;

TEST(SurfaceOnly, MshWithVolumeEntitiesHasItsVolumesMeshedAndOptimized) {
  const std::string dir = testing::temp_dir();
  const std::string msh = mesh_geo(dir, kTwoBoxes, "", "two_surf.msh");
  const GmshDump in = gmsh_dump(msh);
  std::set<int> types_in;
  for (const auto& [tag, e] : in.elements) types_in.insert(std::get<0>(e));
  ASSERT_EQ(types_in.count(4), 0u) << "the file holds tets: not the case under test";
  ASSERT_EQ(types_in.count(2), 1u);

  const MeshData d = read_mesh(msh);
  ASSERT_EQ(d.dim, 3);
  EXPECT_TRUE(check_mesh(d.tet).ok);
  EXPECT_EQ(std::set<int>(d.tet.tet_region.begin(), d.tet.tet_region.end()), (std::set<int>{1, 2}));
  EXPECT_NEAR(tet_volume(d.tet), 2.0, 1e-9);
  ASSERT_EQ(d.model().read_notes.size(), 1u);

  const std::string out = dir + "/two_opt.msh";
  std::string log;
  ASSERT_EQ(run(testing::cli_path() + " optimize " + msh + " -o " + out, &log), 0) << log;
  EXPECT_NE(log.find("no tetrahedra"), std::string::npos) << log;
  EXPECT_EQ(run(testing::cli_path() + " check " + out, &log), 0) << log;
  const GmshDump o = gmsh_dump(out);
  EXPECT_EQ(in.groups, o.groups);
  std::set<int> types_out;
  for (const auto& [tag, e] : o.elements) types_out.insert(std::get<0>(e));
  EXPECT_EQ(types_out.count(4), 1u) << "no tetrahedra written";
  for (int t : types_in) EXPECT_EQ(types_out.count(t), 1u) << "element type " << t << " dropped";
}

TEST(SurfaceOnly, ClosedSurfaceWithoutVolumesIsTetrahedralizedInEveryMeshFormat) {
  const std::string dir = testing::temp_dir();
  for (const auto& [flags, name] :
       std::vector<std::pair<std::string, std::string>>{{"-format msh22", "cav.msh"},
                                                        {"-format mesh", "cav.mesh"},
                                                        {"-format vtk", "cav.vtk"},
                                                        {"-format unv", "cav.unv"}}) {
    const std::string path = mesh_geo(dir, kBoxWithCavity, flags, name);
    const MeshData d = read_mesh(path);
    ASSERT_EQ(d.dim, 3) << name;
    EXPECT_TRUE(check_mesh(d.tet).ok) << name;
    // The sphere is a cavity (inside one other shell), not a second volume.
    EXPECT_NEAR(tet_volume(d.tet), kCavityVolume, 0.01) << name;
    EXPECT_EQ(d.model().read_notes.size(), 1u) << name;
  }
}

TEST(SurfaceOnly, OpenSurfaceInSpaceIsASurfaceMeshAndWriteOnlyFormatsAreRefusedClearly) {
  const std::string dir = testing::temp_dir();
  // A tilted open square: not a 2D mesh (z varies), bounds no volume: a surface mesh in space
  // (no tets), in VTK and in Medit, where each triangle reference is a surface of its own.
  const std::string vtk = dir + "/open.vtk", medit = dir + "/open.mesh";
  std::ofstream(vtk) << "# vtk DataFile Version 2.0\nopen\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                        "POINTS 4 double\n0 0 0\n1 0 0\n1 1 1\n0 1 1\nCELLS 2 8\n3 0 1 2\n"
                        "3 0 2 3\nCELL_TYPES 2\n5\n5\n";
  std::ofstream(medit) << "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n"
                          "1 1 1 0\n0 1 1 0\nTriangles\n2\n1 2 3 7\n1 3 4 9\nEnd\n";
  for (const auto& [path, surfaces] :
       std::vector<std::pair<std::string, std::set<int>>>{{vtk, {}}, {medit, {7, 9}}}) {
    const MeshData d = read_mesh(path);
    ASSERT_EQ(d.dim, 3) << path;
    EXPECT_EQ(d.tet.nb_tets(), 0) << path;
    EXPECT_EQ(d.tet.tris.size(), 6u) << path;
    const std::set<int> got(d.tet.tri_surface.begin(), d.tet.tri_surface.end());
    if (!surfaces.empty())
      EXPECT_EQ(got, surfaces) << path;
    else
      EXPECT_EQ(got.size(), 1u) << path;
    // Read as 2D (--dim 2) it is refused, naming the file and the defect.
    ReadOptions as_2d;
    as_2d.dim = 2;
    try {
      read_mesh(path, as_2d);
      FAIL() << "an open surface in space was read as 2D";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("no tetrahedra"), std::string::npos) << e.what();
    }
  }
  mesh_geo(dir, kTwoBoxes, "", "unused.msh");  // writes model.geo
  for (const auto& [ext, format] : std::vector<std::pair<std::string, std::string>>{
           {"inp", "Abaqus"}, {"su2", "SU2"}, {"diff", "Diffpack"}}) {
    const std::string path = dir + "/model." + ext;
    std::string log;
    ASSERT_EQ(run("gmsh -v 0 -3 " + dir + "/model.geo -o " + path, &log), 0) << log;
    try {
      read_mesh(path);
      FAIL() << ext << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(format), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace cvtmesh
