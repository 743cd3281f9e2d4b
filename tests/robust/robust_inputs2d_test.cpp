// Planar inputs the 2D optimizer used to refuse or return unchanged (Gmsh's API demos): a crack
// made by Gmsh's Crack plugin (its lips' nodes duplicated), triangles given in mixed orientation
// (Gmsh's own triangulate), and a mesh where the method ends worse than the input.
#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "core/io/read_mesh.h"
#include "core/io/write_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/find_coincident_vertices.h"
#include "core/pipeline/optimize.h"
#include "core/quality/quality_stats.h"
#include "core/quality/worse_than.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::string write_text(const std::string& name, const std::string& text) {
  const std::string path = testing::temp_dir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

bool has_note(const OptimizeResult& r, const std::string& word) {
  for (const auto& n : r.notes)
    if (n.find(word) != std::string::npos) return true;
  return false;
}

std::vector<std::array<int, 2>> coincident_pairs(const TriMesh2& m) {
  std::vector<double> xyz;
  for (int v = 0; v < m.nb_vertices(); ++v)
    xyz.insert(xyz.end(), {m.xy[2 * v], m.xy[2 * v + 1], 0});
  std::vector<char> used(m.nb_vertices(), 0);
  for (int v : m.tris) used[v] = 1;
  return find_coincident_vertices(xyz, used, 1e-10);
}

std::string check_output(const MeshData& d, const std::string& name, std::string* out) {
  const std::string path = testing::temp_dir() + "/" + name;
  write_mesh(d, path);
  testing::run(testing::cli_path() + " check " + path, out);
  return path;
}

// A square with a crack inside (a line embedded in the surface), its nodes duplicated by Gmsh's
// Crack plugin: served (no Delaunay rebuild), the lips keep matching, never worse, checked.
TEST(RobustInputs2d, CrackLipsKeepMatchingIn2d) {
  MeshData d = read_mesh(write_text(
      "crack2d.geo",
      "Point(1) = {0,0,0,0.12};\nPoint(2) = {1,0,0,0.12};\nPoint(3) = {1,1,0,0.12};\n"
      "Point(4) = {0,1,0,0.12};\nPoint(5) = {0.2,0.45,0,0.05};\nPoint(6) = {0.8,0.55,0,0.05};\n"
      "Line(1) = {1,2};\nLine(2) = {2,3};\nLine(3) = {3,4};\nLine(4) = {4,1};\n"
      "Line(5) = {5,6};\nCurve Loop(1) = {1,2,3,4};\nPlane Surface(1) = {1};\n"
      "Line{5} In Surface{1};\nPhysical Curve(10) = {5};\nPhysical Curve(11) = {1,2,3,4};\n"
      "Physical Surface(1) = {1};\nMesh 2;\nPlugin(Crack).Dimension = 1;\n"
      "Plugin(Crack).PhysicalGroup = 10;\nPlugin(Crack).Run;\n"));
  ASSERT_EQ(d.dim, 2);
  const auto pairs = coincident_pairs(d.tri);
  ASSERT_FALSE(pairs.empty());
  const TriMesh2 input = d.tri;
  const OptimizeResult r = optimize(d, OptimizeOptions{});
  EXPECT_TRUE(has_note(r, "coincide")) << (r.notes.empty() ? "" : r.notes[0]);
  EXPECT_FALSE(r.kept_input);
  const MeshCheck c = check_mesh(d.tri);
  ASSERT_TRUE(c.ok) << c.problems.front();
  EXPECT_EQ(worse_than(quality_stats(d.tri, ""), r.before), "");
  EXPECT_GT(r.after.q_avg, r.before.q_avg);
  // Each input pair of coincident nodes is still a pair at the same place; both lips' lines kept.
  std::map<std::array<double, 2>, int> at;
  for (int v = 0; v < d.tri.nb_vertices(); ++v) ++at[{d.tri.xy[2 * v], d.tri.xy[2 * v + 1]}];
  for (const auto& [a, b] : pairs) {
    EXPECT_EQ((at[{input.xy[2 * a], input.xy[2 * a + 1]}]), 2) << "node " << a;
    (void)b;
  }
  EXPECT_EQ(d.tri.edges, input.edges);
  std::string out;
  check_output(d, "crack2d_out.msh", &out);
  EXPECT_NE(out.find(": ok"), std::string::npos) << out;
  EXPECT_NE(out.find("pairs of nodes at the same place"), std::string::npos) << out;  // a warning
}

// A 3 x 3 grid of nodes, 8 triangles of which `turned` are given clockwise; `centre` moves the
// middle node. No lines: the boundary comes from the triangles.
std::string grid_msh(const std::string& name, const std::vector<int>& turned,
                     std::array<double, 2> centre = {1, 1}) {
  std::ostringstream s;
  s << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n9\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const bool mid = i == 1 && j == 1;
      s << 1 + i + 3 * j << " " << (mid ? centre[0] : i) << " " << (mid ? centre[1] : j) << " 0\n";
    }
  s << "$EndNodes\n$Elements\n8\n";
  int k = 0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = 1 + i + 3 * j, b = a + 1, c = a + 4, dd = a + 3;
      for (std::array<int, 3> t : {std::array<int, 3>{a, b, c}, std::array<int, 3>{a, c, dd}}) {
        if (std::find(turned.begin(), turned.end(), k) != turned.end()) std::swap(t[1], t[2]);
        s << ++k << " 2 2 1 1 " << t[0] << " " << t[1] << " " << t[2] << "\n";
      }
    }
  s << "$EndElements\n";
  return write_text(name, s.str());
}

TEST(RobustInputs2d, MixedOrientationTrianglesAreTurnedAndRead) {
  const std::string path = grid_msh("mixed.msh", {1, 4, 6}, {0.8, 1.1});
  MeshData d = read_mesh(path);
  ASSERT_EQ(d.dim, 2);
  EXPECT_EQ(d.model().nb_reoriented, 3);
  EXPECT_TRUE(d.tri.cw_surfaces.empty());  // the majority: counter-clockwise
  EXPECT_TRUE(check_mesh(d.tri).ok);
  std::string out;
  EXPECT_EQ(testing::run(testing::cli_path() + " check " + path, &out), 5) << out;
  EXPECT_NE(out.find("turn the other way round"), std::string::npos) << out;
  const OptimizeResult r = optimize(d, OptimizeOptions{});
  EXPECT_TRUE(check_mesh(d.tri).ok);
  EXPECT_EQ(worse_than(quality_stats(d.tri, ""), r.before), "");
  const std::string written = check_output(d, "mixed_out.msh", &out);
  EXPECT_NE(out.find(": ok"), std::string::npos) << out;
  const MeshData back = read_mesh(written);
  EXPECT_EQ(back.model().nb_reoriented, 0);
  EXPECT_TRUE(back.tri.cw_surfaces.empty());
}

TEST(RobustInputs2d, MixedOrientationKeepsAClockwiseSurfaceClockwise) {
  // 6 of 8 clockwise: the surface is clockwise, the two others turned to it.
  const std::string path = grid_msh("mostly_cw.msh", {0, 1, 2, 3, 5, 7});
  MeshData d = read_mesh(path);
  EXPECT_EQ(d.model().nb_reoriented, 2);
  EXPECT_EQ(d.tri.cw_surfaces, std::vector<int>{1});
  optimize(d, OptimizeOptions{});
  const std::string written = testing::temp_dir() + "/mostly_cw_out.msh";
  write_mesh(d, written);
  const MeshData back = read_mesh(written);
  EXPECT_EQ(back.model().nb_reoriented, 0);
  EXPECT_EQ(back.tri.cw_surfaces, std::vector<int>{1});
}

TEST(RobustInputs2d, TangledTrianglesAreRefusedOnceTurned) {
  // The middle node outside its star: two triangles turn over and, turned back, overlap.
  const std::string path = grid_msh("tangled.msh", {}, {2.5, 1.0});
  try {
    read_mesh(path);
    FAIL() << "a tangled mesh was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("do not form a mesh"), std::string::npos) << e.what();
  }
}

// Gmsh's demo boolean/fragment_numbering (a strip of rectangles and ten small disks fragmented
// together): 'cvdt' cannot lower the maximum angle of the input's worst triangle (a disk's sliver
// against the strip) and the restore cannot mend it. The input is not returned unchanged: the
// never-worse local operations improve it, and no row is worse.
const char* kFragmentNumbering =
    "SetFactory(\"OpenCASCADE\");\nw = 0.05; N = 10; R = 0.002; spacing = 0;\n"
    "Rectangle(1) = {-3*w, w, 0, 6*w, w, 0};\nRectangle(2) = {-3*w, 0., 0, w, w, 0};\n"
    "Translate {2*w, 0, 0} { Duplicata { Surface{2}; } }\n"
    "Translate {w, 0, 0} { Duplicata { Surface{3}; } }\n"
    "Translate {2*w, 0, 0} { Duplicata { Surface{4}; } }\n"
    "Rectangle(6) = {-6*w, 0, 0, 12*w, 5*w, 0};\nb() = Boundary{ Surface{6}; };\nt = b(2);\n"
    "b() = {};\nFor i In {1:N}\n  s = news; b() += s; "
    "Disk(s) = {-w-R-spacing, (2*R+spacing)*i, 0, R};\nEndFor\n"
    "c() = BooleanFragments{ Curve{t}; Surface{1:6,b()}; Delete; }{};\n";

TEST(RobustInputs2d, AMethodEndingWorseFallsBackOnLocalOperationsNotTheInput) {
  MeshData d = read_mesh(write_text("fragment_numbering.geo", kFragmentNumbering), {.dim = 2});
  ASSERT_EQ(d.dim, 2);
  const TriMesh2 input = d.tri;
  OptimizeOptions o;
  o.method = "cvdt";  // named: no final pass, only the fallback
  const OptimizeResult r = optimize(d, o);
  ASSERT_TRUE(has_note(r, "made the mesh worse")) << (r.notes.empty() ? "" : r.notes[0]);
  EXPECT_TRUE(has_note(r, "improved by local operations")) << r.notes[0];
  EXPECT_FALSE(r.kept_input);
  EXPECT_NE(d.tri.xy, input.xy);
  const MeshCheck c = check_mesh(d.tri);
  ASSERT_TRUE(c.ok) << c.problems.front();
  const QualityStats after = quality_stats(d.tri, "");
  EXPECT_EQ(worse_than(after, r.before), "");
  EXPECT_GT(after.q_avg, r.before.q_avg);
  for (int v = 0; v < d.tri.nb_vertices(); ++v)  // corners and curve nodes stay
    if (input.vclass[v].dim < 2) {
      EXPECT_EQ(d.tri.xy[2 * v], input.xy[2 * v]);
      EXPECT_EQ(d.tri.xy[2 * v + 1], input.xy[2 * v + 1]);
    }
}

// The default run ends with the local pass; the paper's method named explicitly does not (its
// result is the paper's).
TEST(RobustInputs2d, OnlyTheDefaultRunEndsWithTheLocalPass) {
  const std::string geo = testing::geo_path("washer.geo");
  MeshData named = read_mesh(geo, {.dim = 2});
  MeshData plain = named;
  OptimizeOptions o;
  o.method = "cvdt";
  o.max_iterations = 50;
  const OptimizeResult rn = optimize(named, o);
  EXPECT_FALSE(has_note(rn, "improved by local operations"));
  OptimizeOptions def;
  def.max_iterations = 50;
  const OptimizeResult rd = optimize(plain, def);
  EXPECT_TRUE(has_note(rd, "improved by local operations"));
  EXPECT_EQ(worse_than(rd.after, rn.after), "");
  EXPECT_GT(rd.after.q_avg, rn.after.q_avg);
  EXPECT_TRUE(check_mesh(plain.tri).ok);
}

// Two surfaces touching at a corner through two distinct points at one place (as in Gmsh's
// tutorial t6): the Lloyd step's Delaunay triangulation of every vertex cannot take the pair, so
// the run goes local, pins them, and the mesh is served, not refused.
TEST(RobustInputs2d, SurfacesTouchingAtACornerWithTwoNodesThereAreServed) {
  const std::string geo =
      write_text("touching_corner.geo",
                 "Point(1) = {0,0,0,0.2}; Point(2) = {1,0,0,0.2}; Point(3) = {1,1,0,0.2};\n"
                 "Point(4) = {0,1,0,0.2}; Point(5) = {1,1,0,0.2}; Point(6) = {2,1,0,0.2};\n"
                 "Point(7) = {2,2,0,0.2}; Point(8) = {1,2,0,0.2};\n"
                 "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};\n"
                 "Line(5) = {5,6}; Line(6) = {6,7}; Line(7) = {7,8}; Line(8) = {8,5};\n"
                 "Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};\n"
                 "Curve Loop(2) = {5,6,7,8}; Plane Surface(2) = {2};\n"
                 "Transfinite Curve{1,2,3,4} = 6; Transfinite Surface{1}; Recombine Surface{1};\n");
  MeshData d = read_mesh(geo);
  ASSERT_EQ(d.dim, 2);
  const OptimizeResult r = optimize(d, OptimizeOptions{});
  EXPECT_TRUE(check_mesh(d.tri).ok);
  EXPECT_EQ(worse_than(quality_stats(d.tri, ""), r.before), "");
  EXPECT_TRUE(has_note(r, "coincide")) << (r.notes.empty() ? "" : r.notes.front());
}

}  // namespace
}  // namespace cvtmesh
