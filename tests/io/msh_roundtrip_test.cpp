// .msh -> MeshData -> .msh round trips (4.1 and 2.2), and the --quality views inside the .msh.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <fstream>
#include <set>

#include "core/quality/quality_fields.h"
#include "core/mesh/mesh_data.h"
#include "core/io/read_mesh.h"
#include "core/io/write_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/util/error.h"
#include "tests/io/gmsh_dump.h"
#include "tests/io/mesh_compare.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

using testing::canon;
using testing::gmsh_dump;

// A .msh written by Gmsh itself (the gmsh executable), as a user would bring it.
std::string gmsh_made_msh(const std::string& dir, const std::string& geo, const std::string& args,
                          const std::string& name) {
  const std::string out = dir + "/" + name;
  std::string log;
  const int rc = testing::run("gmsh -v 0 " + geo + " " + args + " -o " + out, &log);
  EXPECT_EQ(rc, 0) << log;
  return out;
}

void expect_same_gmsh_model(const std::string& a, const std::string& b) {
  const testing::GmshDump da = gmsh_dump(a), db = gmsh_dump(b);
  EXPECT_GT(da.nodes.size(), 0u);
  EXPECT_EQ(da.entities, db.entities) << "entities or their boundaries differ";
  EXPECT_EQ(da.groups, db.groups) << "physical groups differ";
  EXPECT_EQ(da.nodes.size(), db.nodes.size());
  EXPECT_TRUE(da.nodes == db.nodes) << "node tags, coordinates or classification differ";
  EXPECT_EQ(da.elements.size(), db.elements.size());
  EXPECT_TRUE(da.elements == db.elements) << "element tags, types, entities or nodes differ";
}

void round_trip_41(const std::string& original) {
  const std::string dir = testing::temp_dir();
  const MeshData d1 = read_mesh(original);
  ASSERT_TRUE(d1.dim == 3 ? check_mesh(d1.tet).ok : check_mesh(d1.tri).ok);
  const std::string copy = dir + "/copy.msh";
  write_mesh(d1, copy);
  const MeshData d2 = read_mesh(copy);
  EXPECT_TRUE(canon(d1) == canon(d2)) << "MeshData differs after .msh 4.1 -> MeshData -> .msh";
  // Binary .msh too.
  WriteOptions bin;
  bin.binary = true;
  const std::string copy_bin = dir + "/copy_bin.msh";
  write_mesh(d1, copy_bin, bin);
  EXPECT_TRUE(canon(d1) == canon(read_mesh(copy_bin))) << "binary .msh round trip differs";
  // And Gmsh itself sees the same model in both files.
  expect_same_gmsh_model(original, copy);
}

TEST(MshRoundTrip, CubeSphere41IsExact) {
  const std::string dir = testing::temp_dir();
  round_trip_41(gmsh_made_msh(dir, testing::geo_path("cube_sphere.geo"), "-3", "cs.msh"));
}

// Gmsh saves only the elements of physical groups unless told otherwise: the triangles of the
// surfaces outside every group are not in the file. They are restored on the right surfaces.
TEST(MshRoundTrip, MissingBoundaryTrianglesAreRestoredOnTheirSurfaces) {
  const std::string dir = testing::temp_dir();
  const std::string geo = testing::geo_path("cube_sphere.geo");
  const std::string part = gmsh_made_msh(dir, geo, "-3 -setnumber two_regions 1", "part.msh");
  const std::string all =
      gmsh_made_msh(dir, geo, "-3 -save_all -setnumber two_regions 1", "all.msh");
  const MeshData dp = read_mesh(part), da = read_mesh(all);
  ASSERT_LT(gmsh_dump(part).elements.size(), gmsh_dump(all).elements.size())
      << "the physical-groups-only file should lack elements";
  // Same mesh (Gmsh meshes deterministically), same boundary triangles on the same surfaces.
  ASSERT_EQ(dp.tet.nb_tets(), da.tet.nb_tets());
  std::map<std::array<std::size_t, 3>, int> fp, fa;
  auto faces = [](const TetMesh& m, std::map<std::array<std::size_t, 3>, int>& out) {
    for (int f = 0; f < m.nb_tris(); ++f) {
      std::array<std::size_t, 3> k;
      for (int j = 0; j < 3; ++j) k[j] = m.node_tags[m.tris[3 * f + j]];
      std::sort(k.begin(), k.end());
      out[k] = m.tri_surface[f];
    }
  };
  faces(dp.tet, fp);
  faces(da.tet, fa);
  EXPECT_EQ(fp.size(), fa.size());
  EXPECT_TRUE(fp == fa) << "restored triangles are not on the surfaces Gmsh put them on";
}

TEST(MshRoundTrip, TwoRegionCubeSphere41IsExact) {
  const std::string dir = testing::temp_dir();
  const std::string msh = gmsh_made_msh(dir, testing::geo_path("cube_sphere.geo"),
                                        "-3 -save_all -setnumber two_regions 1", "cs2.msh");
  const MeshData d = read_mesh(msh);
  ASSERT_EQ(d.dim, 3);
  std::set<int> regions(d.tet.tet_region.begin(), d.tet.tet_region.end());
  EXPECT_EQ(regions.size(), 2u) << "the two-region variant must have two regions";
  round_trip_41(msh);
}

TEST(MshRoundTrip, PlanarMesh41IsExact) {
  const std::string dir = testing::temp_dir();
  const std::string geo = dir + "/plate.geo";
  std::ofstream(geo) << "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 2, 1};\n"
                        "Disk(2) = {0.6, 0.5, 0, 0.25};\n"
                        "BooleanDifference(3) = {Surface{1}; Delete;}{Surface{2}; Delete;};\n"
                        "Physical Surface(\"plate\", 7) = {3};\n"
                        "Physical Curve(\"hole\", 8) = {5};\nMesh.MeshSizeMax = 0.1;\n";
  round_trip_41(gmsh_made_msh(dir, geo, "-2 -save_all", "plate.msh"));
}

// MSH 2.2 stores groups only as element tags: a mesh with elements outside every group next to
// groups cannot be written as 2.2 without losing one or the other; refused, nothing written.
TEST(MshRoundTrip, Msh22RefusesElementsOutsideGroups) {
  const std::string dir = testing::temp_dir();
  const std::string msh = gmsh_made_msh(dir, testing::geo_path("cube_sphere.geo"),
                                        "-3 -save_all -setnumber two_regions 1", "cs2all.msh");
  const MeshData d = read_mesh(msh);
  WriteOptions o;
  o.msh_version = 2.2;
  const std::string v22 = dir + "/all22.msh";
  try {
    write_mesh(d, v22, o);
    ADD_FAILURE() << "expected an OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("physical group"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(v22));
}

TEST(MshRoundTrip, Msh22KeepsTagsAndGroups) {
  const std::string dir = testing::temp_dir();
  // As Gmsh saves a model with groups: only their elements (every one in a group).
  const std::string msh = gmsh_made_msh(dir, testing::geo_path("cube_sphere.geo"),
                                        "-3 -setnumber two_regions 1", "cs2.msh");
  const MeshData d1 = read_mesh(msh);
  WriteOptions o;
  o.msh_version = 2.2;
  const std::string v22 = dir + "/copy22.msh";
  write_mesh(d1, v22, o);
  {
    std::ifstream in(v22);
    std::string line;
    std::getline(in, line);
    std::getline(in, line);
    EXPECT_EQ(line.rfind("2.2", 0), 0u) << "not a 2.2 file: " << line;
  }
  const MeshData d2 = read_mesh(v22);
  testing::MeshCanon c1 = canon(d1), c2 = canon(d2);
  // Node tags and coordinates are kept; MSH 2.2 has no $Entities section, so the classification
  // of nodes on entities without written elements (curves and points outside the groups) is not
  // in the file — as in Gmsh's own 2.2 output of the model.
  ASSERT_EQ(c1.nodes.size(), c2.nodes.size());
  for (const auto& [tag, n] : c1.nodes) {
    auto it = c2.nodes.find(tag);
    ASSERT_NE(it, c2.nodes.end()) << "node " << tag;
    EXPECT_EQ(std::get<0>(n), std::get<0>(it->second));
    EXPECT_EQ(std::get<1>(n), std::get<1>(it->second));
    EXPECT_EQ(std::get<2>(n), std::get<2>(it->second));
  }
  EXPECT_TRUE(c1.cells == c2.cells) << "tet tags, regions or nodes differ";
  EXPECT_EQ(c1.groups, c2.groups);
  // The triangles of the grouped surfaces keep their tags and surfaces.
  std::set<int> grouped;
  for (const auto& g : d1.model().groups)
    if (g.dim == 2) grouped.insert(g.entities.begin(), g.entities.end());
  ASSERT_FALSE(grouped.empty());
  auto grouped_facets = [&](const testing::MeshCanon& c) {
    std::map<std::size_t, std::pair<int, std::vector<std::size_t>>> f;
    for (const auto& [tag, x] : c.facets)
      if (grouped.count(x.first)) f[tag] = x;
    return f;
  };
  EXPECT_FALSE(grouped_facets(c1).empty());
  EXPECT_TRUE(grouped_facets(c1) == grouped_facets(c2));
  // The entities that hold written elements come back.
  std::set<std::pair<int, int>> e1, e2;
  for (int r : d1.tet.tet_region) e1.insert({3, r});
  for (int s : d1.tet.tri_surface)
    if (grouped.count(s)) e1.insert({2, s});
  for (const auto& [k, b] : c2.entities) e2.insert(k);
  for (const auto& e : e1) EXPECT_TRUE(e2.count(e)) << e.first << "," << e.second;
}

TEST(MshQualityViews, OpenInGmshWithOurPerElementValues) {
  const std::string dir = testing::temp_dir();
  const MeshData d = read_mesh(testing::geo_path("cube_sphere.geo"));
  const std::vector<ElementField> fields = quality_fields(d);
  ASSERT_EQ(fields.size(), 3u);
  for (const bool binary : {false, true}) {
    SCOPED_TRACE(binary ? "binary" : "ASCII");
    WriteOptions o;
    o.fields = fields;
    o.binary = binary;
    const std::string out = dir + (binary ? "/qb.msh" : "/q.msh");
    write_mesh(d, out, o);
    const testing::GmshDump dump = gmsh_dump(out);
    ASSERT_EQ(dump.views.size(), 3u);
    // The views do not get in the way of reading the mesh back.
    const MeshData back = read_mesh(out);
    // One value per written element (what meshio needs), elements numbered 1..N in file order:
    // each tet's value is its quality, every other element's NaN.
    const std::vector<ElementField> back_fields = quality_fields(back);
    for (std::size_t k = 0; k < fields.size(); ++k) {
      auto it = dump.views.find(fields[k].name);
      ASSERT_NE(it, dump.views.end()) << "no view '" << fields[k].name << "'";
      ASSERT_EQ(it->second.size(), dump.elements.size());
      EXPECT_EQ(it->second.begin()->first, 1u);
      EXPECT_EQ(it->second.rbegin()->first, dump.elements.size());
      std::size_t nb_values = 0;
      for (const auto& [tag, v] : it->second) nb_values += !std::isnan(v);
      EXPECT_EQ(nb_values, fields[k].values.size());
      for (int t = 0; t < back.tet.nb_tets(); ++t) {
        const double want = back_fields[k].values[t];
        const double got = it->second.at(back.tet.tet_tags[t]);
        EXPECT_NEAR(got, want, 1e-12 * std::max(1.0, std::fabs(want))) << fields[k].name;
      }
    }
    // (The mesh came from a .geo: Gmsh's ASCII .msh writer prints 16 significant digits, so the
    // coordinates agree to the last bit or so; a .msh -> .msh round trip is exact, see above.)
    // (Elements are renumbered in file order; the nodes keep their tags.)
    const testing::MeshCanon a = canon(back), b = canon(d);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (const auto& [tag, n] : b.nodes) {
      auto it = a.nodes.find(tag);
      ASSERT_NE(it, a.nodes.end());
      EXPECT_NEAR(std::get<0>(it->second), std::get<0>(n), 1e-15);
      EXPECT_NEAR(std::get<1>(it->second), std::get<1>(n), 1e-15);
      EXPECT_NEAR(std::get<2>(it->second), std::get<2>(n), 1e-15);
      EXPECT_EQ(std::get<3>(it->second), std::get<3>(n));
      EXPECT_EQ(std::get<4>(it->second), std::get<4>(n));
    }
    // The same tets and boundary triangles by their nodes.
    auto by_nodes = [](const auto& m) {
      std::multiset<std::pair<int, std::vector<std::size_t>>> s;
      for (const auto& [tag, c] : m) s.insert(c);
      return s;
    };
    EXPECT_TRUE(by_nodes(a.cells) == by_nodes(b.cells));
    EXPECT_TRUE(by_nodes(a.facets) == by_nodes(b.facets));
    EXPECT_TRUE(a.groups == b.groups);
  }
}

}  // namespace
}  // namespace cvtmesh
