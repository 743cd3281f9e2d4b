// Planar hybrid meshes (triangles and quadrangles, Gmsh's Recombine) and planar meshes with
// curves that bound no surface, through `cvtmesh optimize` and `check`: meshed by Gmsh from
// .geo text here, read back through the Gmsh API (gmsh_dump.h), and checked for what must hold:
// every element, line, point and group kept with its nodes, the boundary nodes unmoved, every
// quadrangle strictly convex and every triangle positive, the area kept, the minimum scaled
// Jacobian and triangle Q not lower than the input's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/geometry/predicates.h"
#include "core/io/read_mesh.h"
#include "core/mesh/check_quads2d.h"
#include "core/quality/quad_scaled_jacobian.h"
#include "core/quality/quality.h"
#include "tests/io/gmsh_dump.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

using testing::gmsh_dump;
using testing::GmshDump;

std::string mesh_geo(const std::string& dir, const std::string& name, const std::string& body) {
  const std::string geo = dir + "/" + name + ".geo", msh = dir + "/" + name + ".msh";
  std::ofstream(geo) << body;
  std::string log;
  EXPECT_EQ(testing::run("gmsh -v 0 -2 " + geo + " -o " + msh, &log), 0) << log;
  return msh;
}

// `cvtmesh optimize in -o out`, then `cvtmesh check out`: both must succeed.
std::string optimize(const std::string& in) {
  const std::string out = in.substr(0, in.size() - 4) + "_opt.msh";
  std::string log;
  EXPECT_EQ(testing::run(testing::cli_path() + " optimize " + in + " -o " + out, &log), 0) << log;
  EXPECT_EQ(testing::run(testing::cli_path() + " check " + out, &log), 0) << log;
  return out;
}

// What the test measures on a dumped planar mesh, each surface in its own turning sense (the
// sign of its elements' total signed area).
struct Measured {
  long nb_tris = 0, nb_quads = 0, nb_bad_tris = 0, nb_bad_quads = 0;
  double area = 0, sj_min = std::numeric_limits<double>::infinity(), tq_min = 2;
  double sj_sum = 0, tq_sum = 0;
  double sj_avg() const { return sj_sum / nb_quads; }
  double tq_avg() const { return tq_sum / nb_tris; }
};

Measured measure(const GmshDump& d) {
  auto xy = [&](std::size_t tag) {
    const auto& n = d.nodes.at(tag);
    return std::array<double, 2>{std::get<0>(n), std::get<1>(n)};
  };
  std::map<int, double> surface_area;
  for (const auto& [tag, e] : d.elements) {
    const auto& [type, dim, entity, nodes] = e;
    if (type != 2 && type != 3) continue;
    for (std::size_t k = 1; k + 1 < nodes.size(); ++k) {
      const auto a = xy(nodes[0]), b = xy(nodes[k]), c = xy(nodes[k + 1]);
      surface_area[entity] += 0.5 * orient2d(a.data(), b.data(), c.data());
    }
  }
  Measured m;
  for (const auto& [tag, e] : d.elements) {
    const auto& [type, dim, entity, nodes] = e;
    if (type != 2 && type != 3) continue;
    std::vector<std::array<double, 2>> p;
    for (std::size_t n : nodes) p.push_back(xy(n));
    if (surface_area[entity] < 0) std::reverse(p.begin(), p.end());
    if (type == 2) {
      ++m.nb_tris;
      m.nb_bad_tris += orient2d(p[0].data(), p[1].data(), p[2].data()) <= 0;
      const double q = tri_quality(p[0].data(), p[1].data(), p[2].data(), 2, Measure::kQ);
      m.tq_min = std::min(m.tq_min, q);
      m.tq_sum += q;
      m.area += 0.5 * orient2d(p[0].data(), p[1].data(), p[2].data());
    } else {
      ++m.nb_quads;
      m.nb_bad_quads += !quad_strictly_convex(p[0].data(), p[1].data(), p[2].data(), p[3].data());
      m.sj_sum += quad_scaled_jacobian(p[0].data(), p[1].data(), p[2].data(), p[3].data());
      m.sj_min = std::min(m.sj_min,
                          quad_scaled_jacobian(p[0].data(), p[1].data(), p[2].data(), p[3].data()));
      m.area += 0.5 * (orient2d(p[0].data(), p[1].data(), p[2].data()) +
                       orient2d(p[0].data(), p[2].data(), p[3].data()));
    }
  }
  return m;
}

// Every element other than a triangle (tag, type, entity, nodes), the number of triangles of
// each surface (the triangle optimization re-triangulates), every group and node tag kept; every
// node of a curve or a point (on an entity of dimension < 2) exactly where it was. Returns how
// many nodes moved.
long expect_kept(const GmshDump& in, const GmshDump& out) {
  auto split = [](const GmshDump& d) {
    std::map<std::size_t, std::tuple<int, int, int, std::vector<std::size_t>>> other;
    std::map<int, long> tris;
    for (const auto& [tag, e] : d.elements)
      if (std::get<0>(e) == 2)
        ++tris[std::get<2>(e)];
      else
        other.emplace(tag, e);
    return std::make_pair(other, tris);
  };
  const auto [in_other, in_tris] = split(in);
  const auto [out_other, out_tris] = split(out);
  EXPECT_EQ(in_other, out_other);
  EXPECT_EQ(in_tris, out_tris);
  EXPECT_EQ(in.groups, out.groups);
  EXPECT_EQ(in.nodes.size(), out.nodes.size());
  long moved = 0;
  for (const auto& [tag, n] : in.nodes) {
    const auto it = out.nodes.find(tag);
    if (it == out.nodes.end()) {
      ADD_FAILURE() << "node " << tag << " lost";
      continue;
    }
    const bool same = std::get<0>(n) == std::get<0>(it->second) &&
                      std::get<1>(n) == std::get<1>(it->second) &&
                      std::get<2>(n) == std::get<2>(it->second);
    if (std::get<3>(n) < 2)
      EXPECT_TRUE(same) << "node " << tag << " on entity (" << std::get<3>(n) << ", "
                        << std::get<4>(n) << ") moved";
    moved += !same;
  }
  return moved;
}

// Gmsh's tutorial t11 (a recombined square with a graded size field), coarser.
const char* kT11 =
    "Point(1) = {-1.25, -.5, 0}; Point(2) = {1.25, -.5, 0};\n"
    "Point(3) = {1.25, 1.25, 0};  Point(4) = {-1.25, 1.25, 0};\n"
    "Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
    "Curve Loop(4) = {1, 2, 3, 4}; Plane Surface(100) = {4};\n"
    "Field[1] = MathEval;\n"
    "Field[1].F = \"0.03*(1.0+30.*(y-x*x)*(y-x*x) + (1-x)*(1-x))\";\n"
    "Background Field = 1;\nRecombine Surface{100};\n";

TEST(Hybrid2dCli, AllQuadrangleMeshIsSmoothedNeverWorseWithEverythingKept) {
  const std::string dir = testing::temp_dir();
  const std::string in = mesh_geo(dir, "t11", kT11);
  const GmshDump a = gmsh_dump(in);
  const Measured ma = measure(a);
  ASSERT_EQ(ma.nb_tris, 0) << "the case under test is a mesh of quadrangles only";
  ASSERT_GT(ma.nb_quads, 100);
  const GmshDump b = gmsh_dump(optimize(in));
  const long moved = expect_kept(a, b);
  const Measured mb = measure(b);
  EXPECT_EQ(mb.nb_bad_quads, 0);
  EXPECT_GE(mb.sj_min, ma.sj_min);
  EXPECT_GE(mb.sj_avg(), ma.sj_avg() - 1e-12);
  EXPECT_GT(moved, 0) << "the quadrangles were not optimized";
  EXPECT_NEAR(mb.area, ma.area, 1e-12 * ma.area);
  // `stats` gives the quadrangle rows this test measures on its own.
  std::string out;
  ASSERT_EQ(
      testing::run(testing::cli_path() + " stats --format json " + dir + "/t11_opt.msh 2>/dev/null",
                   &out),
      0)
      << out;
  const nlohmann::json j = nlohmann::json::parse(out.substr(out.find('{')));
  EXPECT_EQ(j.at("quadrangles").get<double>(), static_cast<double>(mb.nb_quads));
  EXPECT_NEAR(j.at("quad_scaled_jacobian_min").get<double>(), mb.sj_min, 1e-12);
  EXPECT_NEAR(j.at("quad_scaled_jacobian_avg").get<double>(), mb.sj_avg(), 1e-12);
}

// Two surfaces sharing curve 2, the left one recombined; and a disk recombined with the simple
// algorithm, which leaves triangles among its quadrangles in the same surface.
const char* kTwoSquares =
    "Point(1) = {0,0,0,0.1}; Point(2) = {1,0,0,0.1}; Point(3) = {1,1,0,0.1};\n"
    "Point(4) = {0,1,0,0.1}; Point(5) = {2,0,0,0.1}; Point(6) = {2,1,0,0.1};\n"
    "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};\n"
    "Line(5) = {2,5}; Line(6) = {5,6}; Line(7) = {6,3};\n"
    "Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};\n"
    "Curve Loop(2) = {5,6,7,-2}; Plane Surface(2) = {2};\n"
    "Physical Surface(\"both\", 7) = {1, 2};\n"
    "Physical Curve(\"outer\", 8) = {1, 3, 4, 5, 6, 7};\n"
    "Recombine Surface{1};\n";
const char* kMixedDisk =
    "SetFactory(\"OpenCASCADE\");\nDisk(1) = {0, 0, 0, 1};\nMesh.MeshSizeMax = 0.15;\n"
    "Mesh.RecombinationAlgorithm = 0;\nRecombine Surface{1};\n";

TEST(Hybrid2dCli, TrianglesAndQuadranglesNeverOverlapAndNeitherGetsWorse) {
  const std::string dir = testing::temp_dir();
  for (const auto& [name, geo] :
       {std::pair{"two_squares", kTwoSquares}, {"mixed_disk", kMixedDisk}}) {
    SCOPED_TRACE(name);
    const std::string in = mesh_geo(dir, name, geo);
    const GmshDump a = gmsh_dump(in);
    const Measured ma = measure(a);
    ASSERT_GT(ma.nb_tris, 0);
    ASSERT_GT(ma.nb_quads, 0);
    const GmshDump b = gmsh_dump(optimize(in));
    expect_kept(a, b);
    const Measured mb = measure(b);
    EXPECT_EQ(mb.nb_bad_tris, 0);
    EXPECT_EQ(mb.nb_bad_quads, 0);
    EXPECT_GE(mb.sj_min, ma.sj_min);
    EXPECT_GE(mb.tq_min, ma.tq_min);
    EXPECT_GE(mb.sj_avg(), ma.sj_avg() - 1e-12);
    EXPECT_GE(mb.tq_avg(), ma.tq_avg() - 1e-12);
    EXPECT_NEAR(mb.area, ma.area, 1e-12 * ma.area);
  }
}

// The interface of the two squares is a curve with lines: its nodes stay; inside the mixed disk,
// triangles and quadrangles meet along edges of no line, held as constrained edges (read_mesh).
TEST(Hybrid2dCli, QuadrangleEdgesTowardsTrianglesAreConstrained) {
  const std::string dir = testing::temp_dir();
  const MeshData d = read_mesh(mesh_geo(dir, "mixed_disk", kMixedDisk));
  ASSERT_EQ(d.dim, 2);
  long interface = 0;
  for (int c : d.tri.edge_curve) interface += c < 0;
  EXPECT_GT(interface, 0);
  EXPECT_TRUE(check_quads2d(d.tri).ok());
}

// Gmsh's boolean/spline demo: free curves 1-4 and 101, 201 (lines bounding no triangle) beside a
// plane surface.
const char* kSpline =
    "SetFactory(\"OpenCASCADE\");\nMesh.Algorithm = 6;\nMesh.MeshSizeMin = 1;\n"
    "Mesh.MeshSizeMax = 1;\n"
    "For i In {1:10}\n  Point(i) = {i, Sin(i/9*2*Pi), 0};\nEndFor\n"
    "Line(1) = {1,10};\nBezier(2) = {1:10};\nSpline(3) = {1:10};\nBSpline(4) = {1:10};\n"
    "Point(101) = {0.2,-1.6,0,0.1};\nPoint(102) = {1.2,-1.6,0,0.1};\n"
    "Point(103) = {1.2,-1.1,0,0.1};\nPoint(104) = {0.3,-1.1,0,0.1};\n"
    "Point(105) = {0.7,-1,0,0.1};\n"
    "Spline(100) = {103,102,101,104,105,103};\nCurve Loop(100) = {100};\n"
    "Plane Surface(100) = {100};\nBSpline(101) = {103,102,101,104,105,103};\n"
    "Point(201) = {0,-2,0,0.1};\nPoint(202) = {1,-2,0,0.1};\nPoint(203) = {1,-3,0,0.1};\n"
    "Point(204) = {0,-3,0,0.1};\n"
    "Nurbs(201) = {201,202,203,204} Knots {0,0,0, 0.5, 1,1,1} Order 2;\n";

TEST(Hybrid2dCli, FreeCurvesAreKeptWithTheirNodesInPlace) {
  const std::string dir = testing::temp_dir();
  const std::string in = mesh_geo(dir, "spline", kSpline);
  const GmshDump a = gmsh_dump(in);
  // The case under test: lines on curves that bound no surface.
  std::set<std::pair<std::size_t, std::size_t>> tri_edges;
  for (const auto& [tag, e] : a.elements)
    if (std::get<0>(e) == 2)
      for (int k = 0; k < 3; ++k) {
        const auto& n = std::get<3>(e);
        tri_edges.insert(std::minmax(n[k], n[(k + 1) % 3]));
      }
  long free_lines = 0;
  for (const auto& [tag, e] : a.elements)
    if (std::get<0>(e) == 1)
      free_lines += !tri_edges.count(std::minmax(std::get<3>(e)[0], std::get<3>(e)[1]));
  ASSERT_GT(free_lines, 10);
  const GmshDump b = gmsh_dump(optimize(in));
  expect_kept(a, b);  // every line and point, their nodes exactly where they were
  const Measured mb = measure(b);
  EXPECT_EQ(mb.nb_bad_tris, 0);
  EXPECT_NEAR(mb.area, measure(a).area, 1e-12 * measure(a).area);
}

// A curve embedded in a surface: its lines are on triangle edges inside, constrained as before.
TEST(Hybrid2dCli, AnEmbeddedCurveStaysAConstraintOfTheTriangles) {
  const std::string dir = testing::temp_dir();
  const std::string in = mesh_geo(
      dir, "embedded",
      "Point(1) = {0,0,0,0.1}; Point(2) = {1,0,0,0.1}; Point(3) = {1,1,0,0.1};\n"
      "Point(4) = {0,1,0,0.1}; Point(5) = {0.3,0.3,0,0.05}; Point(6) = {0.7,0.6,0,0.05};\n"
      "Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1}; Line(5) = {5,6};\n"
      "Curve Loop(1) = {1,2,3,4}; Plane Surface(1) = {1};\nCurve{5} In Surface{1};\n");
  const MeshData d = read_mesh(in);
  long on_curve5 = 0;
  for (int c : d.tri.edge_curve) on_curve5 += c == 5;
  EXPECT_GT(on_curve5, 3);
  for (const ElementBlock& blk : d.tri.model.extra)
    EXPECT_NE(blk.dim, 1) << "a line was not kept as a constraint";
  const std::string out = optimize(in);
  const GmshDump a = gmsh_dump(in), b = gmsh_dump(out);
  EXPECT_GT(expect_kept(a, b), 0);
  const MeshData o = read_mesh(out);
  long out_curve5 = 0;
  for (int c : o.tri.edge_curve) out_curve5 += c == 5;
  EXPECT_EQ(out_curve5, on_curve5);
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

// `check` on quadrangles: a convex one passes, a dart (a reflex corner) and one turned against
// its surface's others are INVALID (exit 5), named by element tag.
TEST(Hybrid2dCli, CheckReportsNonConvexAndInvertedQuadrangles) {
  const std::string dir = testing::temp_dir();
  auto write = [&](const std::string& name, const std::string& elements, int count) {
    const std::string path = dir + "/" + name + ".msh";
    std::ofstream(path) << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n7\n"
                           "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 2 0 0\n6 2 1 0\n7 1.2 0.5 0\n"
                           "$EndNodes\n$Elements\n"
                        << count << "\n"
                        << elements << "$EndElements\n";
    return path;
  };
  std::string log;
  const std::string good = write("good", "1 3 2 0 1 1 2 3 4\n2 3 2 0 1 2 5 6 3\n", 2);
  EXPECT_EQ(testing::run(testing::cli_path() + " check " + good, &log), 0) << log;
  EXPECT_NE(log.find("2 quadrangles"), std::string::npos) << log;
  // Quadrangle 2 with its corner at (1.2, 0.5): reflex.
  const std::string dart = write("dart", "1 3 2 0 1 1 2 3 4\n2 3 2 0 1 2 7 6 3\n", 2);
  EXPECT_EQ(testing::run(testing::cli_path() + " check " + dart, &log), 5) << log;
  EXPECT_NE(log.find("quadrangle 2 "), std::string::npos) << log;
  EXPECT_NE(log.find("not convex"), std::string::npos) << log;
  // Quadrangle 2 clockwise beside two counter-clockwise ones.
  const std::string turned =
      write("turned", "1 3 2 0 1 1 2 3 4\n2 3 2 0 1 2 3 6 5\n3 3 2 0 1 1 2 3 4\n", 3);
  EXPECT_EQ(testing::run(testing::cli_path() + " check " + turned, &log), 5) << log;
  EXPECT_NE(log.find("inverted"), std::string::npos) << log;
}

}  // namespace
}  // namespace cvtmesh
