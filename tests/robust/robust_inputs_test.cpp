// Regression tests for issue 14, one small model per class of real-world input that crashed or
// was refused: a self-intersecting boundary, coincident nodes, orphan nodes, a surface bounding
// no volume, a prism layer, an order-2 mesh, coordinates that must survive a 16-digit writer,
// and the never-worse guarantee.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <iterator>
#include <string>

#include "core/geometry/round_coordinates.h"
#include "core/io/read_mesh.h"
#include "core/io/write_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/constrain_kept_cell_faces.h"
#include "core/pipeline/find_structural_defects.h"
#include "core/pipeline/volumes_apart.h"
#include "core/mesh/extract_regions.h"
#include "core/pipeline/optimize.h"
#include "core/pipeline/verify_mesh.h"
#include "core/quality/quality_stats.h"
#include "core/quality/worse_than.h"
#include "core/util/error.h"
#include "core/mesh/pin_vertices.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::string write_geo(const std::string& name, const std::string& text) {
  const std::string path = testing::temp_dir() + "/" + name + ".geo";
  std::ofstream(path) << text;
  return path;
}

bool has_note(const OptimizeResult& r, const std::string& word) {
  for (const auto& n : r.notes)
    if (n.find(word) != std::string::npos) return true;
  return false;
}

OptimizeOptions quick(const std::string& method = "cvdt+swap+smooth") {
  OptimizeOptions o;
  o.method = method;
  o.max_iterations = 5;
  return o;
}

void expect_valid_and_no_worse(const MeshData& d, const OptimizeResult& r) {
  const MeshCheck c = check_mesh(d.tet);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems.front());
  EXPECT_EQ(worse_than(quality_stats(d.tet, ""), r.before), "");
}

// Two tets, one vertex each side of the other's face: their boundaries cross.
TEST(StructuralDefects, FindsCrossingBoundaryTrianglesAndNotSeparateOnes) {
  TetMesh a = testing::make_tet_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2, 3}});
  auto two = [&](double shift) {
    TetMesh m = a;
    const int n = m.nb_vertices();
    for (int v = 0; v < n; ++v)
      m.xyz.insert(m.xyz.end(), {a.xyz[3 * v] + shift, a.xyz[3 * v + 1] + shift * 0.5,
                                 a.xyz[3 * v + 2] + shift * 0.25});
    for (int f = 0; f < a.nb_tris(); ++f) {
      for (int k = 0; k < 3; ++k) m.tris.push_back(a.tris[3 * f + k] + n);
      m.tri_surface.push_back(2);
    }
    return m;
  };
  EXPECT_FALSE(find_structural_defects(two(0.2)).intersecting_tris.empty());
  EXPECT_TRUE(find_structural_defects(two(3.0)).empty());
  const TetMesh m = two(0.2);
  const auto lines = find_structural_defects(m).describe(m);
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(lines.front().find("surface 2"), std::string::npos) << lines.front();
}

TEST(StructuralDefects, FindsCoincidentNodesOfPartsInContact) {
  TetMesh m = testing::make_tet_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2, 3}});
  // A second tet below the face z = 0, with its own copies of the face's three vertices.
  m.xyz.insert(m.xyz.end(), {0, 0, 0, 1, 0, 0, 0, 1, 1e-12, 0.2, 0.2, -1});
  EXPECT_TRUE(find_structural_defects(m).coincident_vertices.empty());  // unused copies
  m.tris.insert(m.tris.end(), {4, 5, 6});
  m.tri_surface.push_back(3);
  const StructuralDefects d = find_structural_defects(m);
  EXPECT_EQ(d.coincident_vertices.size(), 3u);
  const auto lines = d.describe(m);
  ASSERT_FALSE(lines.empty());
  EXPECT_NE(lines.back().find("node"), std::string::npos);
}

// OCC boxes without a boolean: Gmsh meshes each volume on its own boundary.
const char* kBox = "SetFactory(\"OpenCASCADE\");\nBox(1) = {0,0,0,1,1,1};\n";

// The volumes of `m` and their numbers of tets.
std::map<int, int> tets_per_volume(const TetMesh& m) {
  std::map<int, int> n;
  for (int t = 0; t < m.nb_tets(); ++t) ++n[m.tet_region[t]];
  return n;
}

// Two boxes overlapping (OCC, no boolean): each volume's mesh is valid alone, the whole cannot be
// rebuilt; each volume is optimized apart, the overlap reported as a warning by `check`.
TEST(RobustInputs, OverlappingVolumesAreOptimizedEachApart) {
  MeshData d = read_mesh(write_geo("overlap", std::string(kBox) + "Box(2) = {0.5,0.5,0.5,1,1,1};\n"
                                                                  "Mesh.MeshSizeMax = 0.3;\n"));
  ASSERT_FALSE(find_structural_defects(d.tet).intersecting_tris.empty());
  EXPECT_EQ(volumes_defective_only_together(d.tet), (std::vector<int>{1, 2}));
  const TetMesh input = d.tet;
  const OptimizeResult r = optimize(d, quick());
  EXPECT_TRUE(has_note(r, "each volume optimized apart")) << (r.notes.empty() ? "" : r.notes[0]);
  EXPECT_FALSE(has_note(r, "local operations only"));
  EXPECT_FALSE(r.kept_input);
  expect_valid_and_no_worse(d, r);
  EXPECT_GT(r.after.q_avg, r.before.q_avg);
  // Both volumes there, each still valid alone (the overlap is the input's, nothing new).
  const std::map<int, int> before = tets_per_volume(input), after = tets_per_volume(d.tet);
  ASSERT_EQ(after.size(), before.size());
  for (const auto& [tag, n] : after) {
    EXPECT_GT(n, 0) << "volume " << tag;
    const TetMesh alone = extract_regions(d.tet, {tag}).mesh;
    EXPECT_TRUE(check_mesh(alone).ok) << "volume " << tag;
    EXPECT_TRUE(find_structural_defects(alone).empty()) << "volume " << tag;
  }
  EXPECT_EQ(volumes_defective_only_together(d.tet), (std::vector<int>{1, 2}));
}

// One volume whose own boundary crosses itself: local operations only (no rebuild).
TEST(RobustInputs, SelfIntersectingBoundaryOfOneVolumeIsNotTakenForOverlappingVolumes) {
  TetMesh m = testing::make_tet_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2, 3}});
  const int n = m.nb_vertices(), nf = m.nb_tris();
  for (int v = 0; v < n; ++v)
    m.xyz.insert(m.xyz.end(),
                 {m.xyz[3 * v] + 0.2, m.xyz[3 * v + 1] + 0.1, m.xyz[3 * v + 2] + 0.05});
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) m.tris.push_back(m.tris[3 * f + k] + n);
    m.tri_surface.push_back(2);
  }
  ASSERT_FALSE(find_structural_defects(m).empty());
  EXPECT_TRUE(volumes_defective_only_together(m).empty());
}

TEST(RobustInputs, CoincidentNodesOfTouchingPartsAreOptimizedEachApart) {
  MeshData d = read_mesh(write_geo("touch", std::string(kBox) + "Box(2) = {1,0,0,1,1,1};\n"
                                                                "Mesh.MeshSizeMax = 0.3;\n"));
  ASSERT_FALSE(find_structural_defects(d.tet).coincident_vertices.empty());
  const OptimizeResult r = optimize(d, quick("cvdt"));
  EXPECT_TRUE(has_note(r, "coincide"));
  EXPECT_TRUE(has_note(r, "each volume optimized apart"));
  expect_valid_and_no_worse(d, r);
  EXPECT_EQ(tets_per_volume(d.tet).size(), 2u);
}

TEST(RobustInputs, OrphanNodesAreNotPassedToTetgenAndAreKept) {
  // A meshed wire away from the box and a CAD point duplicating a box corner.
  MeshData d = read_mesh(write_geo("orphans", std::string(kBox) +
                                                  "Point(100) = {2,0,0};\nPoint(101) = {3,0,0};\n"
                                                  "Line(100) = {100,101};\nPoint(102) = {0,0,0};\n"
                                                  "Mesh.MeshSizeMax = 0.3;\n"));
  std::vector<char> used(d.tet.nb_vertices(), 0);
  for (int v : d.tet.tets) used[v] = 1;
  int orphans = 0;
  for (char u : used) orphans += !u;
  ASSERT_GT(orphans, 3);
  const auto extra_before = d.tet.model.extra.size();
  const OptimizeResult r = optimize(d, quick("cvdt"));
  EXPECT_FALSE(has_note(r, "failed")) << (r.notes.empty() ? "" : r.notes.back());
  EXPECT_EQ(d.tet.model.extra.size(), extra_before);
  expect_valid_and_no_worse(d, r);
}

TEST(RobustInputs, SurfaceBoundingNoVolumeIsReadAndWrittenBackUnchanged) {
  MeshData d = read_mesh(write_geo("loose", std::string(kBox) + "Rectangle(50) = {2,0,0,1,1};\n"
                                                                "Mesh.MeshSizeMax = 0.3;\n"));
  long loose = 0;
  for (const auto& b : d.tet.model.extra)
    if (b.dim == 2 && b.entity == 50) loose += static_cast<long>(b.tags.size());
  ASSERT_GT(loose, 4);
  const OptimizeResult r = optimize(d, quick());
  expect_valid_and_no_worse(d, r);
  const std::string out = testing::temp_dir() + "/loose.msh";
  write_mesh(d, out);
  const MeshData back = read_mesh(out);
  long loose_back = 0;
  for (const auto& b : back.tet.model.extra)
    if (b.dim == 2 && b.entity == 50) loose_back += static_cast<long>(b.tags.size());
  EXPECT_EQ(loose_back, loose);
}

// Tets on top of one layer of prisms (extruded with Recombine), conforming.
const char* kPrismLayer =
    "Point(1)={0,0,0,0.3};Point(2)={1,0,0,0.3};Point(3)={1,1,0,0.3};Point(4)={0,1,0,0.3};\n"
    "Line(1)={1,2};Line(2)={2,3};Line(3)={3,4};Line(4)={4,1};\n"
    "Curve Loop(1)={1,2,3,4};Plane Surface(1)={1};\n"
    "a[] = Extrude{0,0,0.2}{Surface{1}; Layers{2}; Recombine;};\n"
    "b[] = Extrude{0,0,0.8}{Surface{a[0]};};\n";

TEST(RobustInputs, PrismLayerIsKeptWithItsVerticesAndTheTetsOptimized) {
  MeshData d = read_mesh(write_geo("prisms", kPrismLayer));
  long prisms = 0;
  std::vector<int> prism_nodes;
  for (const auto& b : d.tet.model.extra)
    if (b.gmsh_type == 6) {
      prisms += static_cast<long>(b.tags.size());
      prism_nodes.insert(prism_nodes.end(), b.nodes.begin(), b.nodes.end());
    }
  ASSERT_GT(prisms, 10);
  ASSERT_GT(d.tet.nb_tets(), 10);
  std::vector<double> before;
  std::vector<std::size_t> tags;
  for (int v : prism_nodes) {
    before.insert(before.end(), d.tet.point(v), d.tet.point(v) + 3);
    tags.push_back(d.tet.node_tags[v]);
  }
  const OptimizeResult r = optimize(d, quick());
  expect_valid_and_no_worse(d, r);
  // Prism vertices unmoved (found by node tag: vertices may be renumbered).
  std::size_t i = 0;
  for (std::size_t k = 0; k < tags.size(); ++k)
    for (int v = 0; v < d.tet.nb_vertices(); ++v)
      if (d.tet.node_tags[v] == tags[k]) {
        for (int c = 0; c < 3; ++c) EXPECT_EQ(d.tet.point(v)[c], before[3 * k + c]);
        ++i;
        break;
      }
  EXPECT_EQ(i, tags.size());
  // Written and read back: the prisms are still there, the interface is not written as triangles.
  const std::string out = testing::temp_dir() + "/prisms.msh";
  write_mesh(d, out);
  const MeshData back = read_mesh(out);
  long prisms_back = 0;
  for (const auto& b : back.tet.model.extra)
    if (b.gmsh_type == 6) prisms_back += static_cast<long>(b.tags.size());
  EXPECT_EQ(prisms_back, prisms);
  EXPECT_EQ(back.tet.nb_tris(), d.tet.nb_tris());
}

TEST(RobustInputs, SecondOrderMeshIsOptimizedOnItsCorners) {
  // Order 2 (tests/io/order2_test.cpp has the end-to-end runs): the corner mesh is optimized and
  // the mesh stays order 2.
  MeshData d = read_mesh(write_geo("order2", std::string(kBox) + "Mesh.MeshSizeMax = 0.5;\n"
                                                                 "Mesh.ElementOrder = 2;\n"));
  EXPECT_EQ(d.model().high_order.order, 2);
  const OptimizeResult r = optimize(d, quick());
  expect_valid_and_no_worse(d, r);
  EXPECT_EQ(d.model().high_order.order, 2);
}

TEST(RobustInputs, OutputCoordinatesAreThoseA16DigitWriterStores) {
  MeshData d = read_mesh(write_geo("box", std::string(kBox) + "Mesh.MeshSizeMax = 0.3;\n"));
  const MeshData in = d;
  OptimizeOptions o = quick();
  o.fix_boundary = true;  // boundary vertices must then come back bit for bit
  const OptimizeResult r = optimize(d, o);
  expect_valid_and_no_worse(d, r);
  // Moved and new vertices hold what a 16-digit writer stores; fixed ones are untouched.
  int unrounded = 0, free = 0;
  for (int v = 0; v < d.tet.nb_vertices(); ++v)
    if (d.tet.vclass[v].dim == 3) {
      ++free;
      for (int c = 0; c < 3; ++c)
        unrounded += d.tet.point(v)[c] != round_to_digits(d.tet.point(v)[c], 16);
    }
  EXPECT_GT(free, 10);
  EXPECT_EQ(unrounded, 0);
  EXPECT_NO_THROW(verify_optimized(in.tet, d.tet));  // boundary vertices exactly as they came
  // The rounding itself: 0.1 + 0.2 is 0.30000000000000004 in memory, 0.3 once written.
  EXPECT_EQ(round_to_digits(0.1 + 0.2, 16), 0.3);
  EXPECT_NE(0.1 + 0.2, 0.3);
}

// Every (dim, node, master node) of the $Periodic links, sorted.
std::vector<std::array<std::size_t, 3>> periodic_pairs(const MeshData& d) {
  std::vector<std::array<std::size_t, 3>> p;
  for (const auto& l : d.tet.model.periodic)
    for (std::size_t i = 0; i < l.node_tags.size(); ++i)
      p.push_back({static_cast<std::size_t>(l.dim), l.node_tags[i], l.master_node_tags[i]});
  std::sort(p.begin(), p.end());
  return p;
}

TEST(RobustInputs, PeriodicPairIsKeptWithItsNodesFixed) {
  MeshData d = read_mesh(write_geo("periodic", std::string(kBox) +
                                                   "Periodic Surface{2} = {1} Translate{1,0,0};\n"
                                                   "Mesh.MeshSizeMax = 0.3;\n"));
  ASSERT_FALSE(d.tet.model.periodic.empty());
  std::size_t pairs = 0;
  for (const auto& l : d.tet.model.periodic) pairs += l.node_tags.size();
  ASSERT_GT(pairs, 10u);
  const OptimizeResult r = optimize(d, quick());
  expect_valid_and_no_worse(d, r);
  for (const double msh : {4.1, 2.2})
    for (const bool binary : {false, true}) {
      const std::string version = (binary ? "binary " : "") + std::to_string(msh);
      WriteOptions w;
      w.binary = binary;
      w.msh_version = msh;
      const std::string out = testing::temp_dir() + "/periodic.msh";
      write_mesh(d, out, w);
      const MeshData back = read_mesh(out);
      std::size_t pairs_back = 0;
      for (const auto& l : back.tet.model.periodic) pairs_back += l.node_tags.size();
      EXPECT_EQ(pairs_back, pairs) << version;
      EXPECT_TRUE(check_mesh(back.tet).ok) << version;
      // The same node pairs as the input's.
      EXPECT_EQ(periodic_pairs(back), periodic_pairs(d)) << version;
    }
}

TEST(RobustInputs, MalformedMsh22PeriodicSectionIsRefusedNamingTheLine) {
  MeshData d = read_mesh(write_geo("periodic22", std::string(kBox) +
                                                     "Periodic Surface{2} = {1} Translate{1,0,0};\n"
                                                     "Mesh.MeshSizeMax = 0.5;\n"));
  WriteOptions w;
  w.msh_version = 2.2;
  const std::string out = testing::temp_dir() + "/periodic22.msh";
  write_mesh(d, out, w);
  // Cut the file inside its $Periodic section.
  std::string text;
  {
    std::ifstream f(out, std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(f), {});
  }
  const auto at = text.find("$Periodic");
  ASSERT_NE(at, std::string::npos);
  std::ofstream(out, std::ios::binary)
      << text.substr(0, at) << "$Periodic\n1\n2 2 1\n3\n1 2\n$EndPeriodic\n";
  try {
    read_mesh(out);
    ADD_FAILURE() << "read a cut $Periodic section";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("$Periodic"), std::string::npos) << e.what();
  }
}

TEST(RobustInputs, OutputTakesTheInputsMshVersionAndMode) {
  MeshData d = read_mesh(write_geo("box22", std::string(kBox) + "Mesh.MeshSizeMax = 0.4;\n"));
  const std::string dir = testing::temp_dir();
  WriteOptions w;
  w.msh_version = 2.2;
  write_mesh(d, dir + "/in22.msh", w);
  w.msh_version = 4.1;
  w.binary = true;
  write_mesh(d, dir + "/in41b.msh", w);
  std::string log;
  ASSERT_EQ(testing::run(testing::cli_path() + " convert " + dir + "/in22.msh " + dir +
                             "/out22.msh && " + testing::cli_path() + " convert " + dir +
                             "/in41b.msh " + dir + "/out41b.msh",
                         &log),
            0)
      << log;
  std::string head;
  testing::run("head -c 40 " + dir + "/out22.msh", &head);
  EXPECT_NE(head.find("2.2 0"), std::string::npos) << head;
  testing::run("head -c 40 " + dir + "/out41b.msh", &head);
  EXPECT_NE(head.find("4.1 1"), std::string::npos) << head;
}

TEST(RobustInputs, WorseThanNamesTheMeasureThatGotWorse) {
  QualityStats a, b;
  a.q_min = 0.2;
  b.q_min = 0.3;
  a.min_angle = b.min_angle = 10;
  a.max_angle = b.max_angle = 150;
  EXPECT_NE(worse_than(a, b).find("Q_min"), std::string::npos);
  EXPECT_EQ(worse_than(b, a), "");
  a.q_min = 0.3;
  a.max_angle = 160;
  EXPECT_NE(worse_than(a, b).find("max"), std::string::npos);
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

// Gmsh's line elements lie on the boundary's curves: pinning them would freeze every curve
// vertex of a free boundary (the femur's 173 curve vertices). Only kept cells and lines off the
// boundary triangles are pinned.
TEST(PinVertices, LinesOnTheBoundaryStayFreeCellsArePinned) {
  TetMesh m = testing::make_tet_mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.2, 0.2, 0.2}},
                                     {{0, 1, 2, 4}, {0, 1, 4, 3}, {0, 4, 2, 3}, {4, 1, 2, 3}}, {4});
  m.vclass[0] = {1, 7};
  m.vclass[1] = {1, 7};
  ElementBlock line;
  line.dim = 1;
  line.entity = 7;
  line.gmsh_type = 1;
  line.tags = {1};
  line.nodes = {0, 1};
  m.model.extra.push_back(line);
  EXPECT_EQ(pin_vertices(m), 0);
  ElementBlock embedded = line;  // a line through the interior vertex
  embedded.nodes = {4, 3};
  m.model.extra.push_back(embedded);
  EXPECT_EQ(pin_vertices(m), 1);
  EXPECT_EQ(m.vclass[4].dim, 0);
  unpin_vertices(m);
  EXPECT_EQ(m.vclass[4].dim, 3);
  ElementBlock prism;
  prism.dim = 3;
  prism.gmsh_type = 6;
  prism.tags = {2};
  prism.nodes = {0, 1, 2, 3, 4, 0};
  m.model.extra = {prism};
  EXPECT_EQ(pin_vertices(m), 5);
  unpin_vertices(m);
  EXPECT_EQ(m.vclass[0].dim, 1);
  EXPECT_EQ(m.vclass[0].entity, 7);
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

// A hexahedron and tets sharing its quadrangle face x = 1 directly (no pyramid, no triangle
// element on it): the tets' two faces there are constrained like a prism's triangle, the hex is
// kept with its vertices fixed, and the interior vertex of the tets is optimized.
TEST(RobustInputs, TetsOnAHexahedronsQuadFaceWithoutTrianglesAreHandled) {
  const std::vector<std::array<double, 3>> p = {
      {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},        {1, 1, 1},
      {0, 1, 1}, {2, 0, 0}, {2, 1, 0}, {2, 0, 1}, {2, 1, 1}, {1.45, 0.55, 0.5}};
  // The cube [1,2]x[0,1]x[0,1] (1-based node ids), each face split in two, coned to node 13.
  const int faces[6][4] = {{2, 3, 7, 6},   {9, 11, 12, 10}, {2, 6, 11, 9},
                           {3, 10, 12, 7}, {2, 9, 10, 3},   {6, 7, 12, 11}};
  std::ostringstream s;
  s << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n" << p.size() << "\n";
  for (std::size_t i = 0; i < p.size(); ++i)
    s << i + 1 << " " << p[i][0] << " " << p[i][1] << " " << p[i][2] << "\n";
  s << "$EndNodes\n$Elements\n13\n1 5 2 0 1 1 2 3 4 5 6 7 8\n";
  int id = 2;
  for (const auto& f : faces) {
    s << id++ << " 4 2 0 2 " << f[0] << " " << f[1] << " " << f[2] << " 13\n";
    s << id++ << " 4 2 0 2 " << f[0] << " " << f[2] << " " << f[3] << " 13\n";
  }
  s << "$EndElements\n";
  const std::string path = testing::temp_dir() + "/hex_tets.msh";
  std::ofstream(path) << s.str();
  MeshData d = read_mesh(path);
  ASSERT_EQ(d.tet.nb_tets(), 12);
  long hexes = 0;
  for (const ElementBlock& b : d.tet.model.extra) hexes += b.gmsh_type == 5 ? b.tags.size() : 0;
  ASSERT_EQ(hexes, 1);
  const MeshData input = d;
  const OptimizeResult r = optimize(d, quick());
  expect_valid_and_no_worse(d, r);
  // The hex's vertices did not move, and the tets still cover its face x = 1 exactly.
  for (int v = 0; v < input.tet.nb_vertices(); ++v)
    if (input.tet.point(v)[0] <= 1)
      for (int k = 0; k < 3; ++k) EXPECT_EQ(d.tet.point(v)[k], input.tet.point(v)[k]);
  double area = 0;
  for (int t = 0; t < d.tet.nb_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      const double* a = d.tet.point(d.tet.tets[4 * t + kTetFace[f][0]]);
      const double* b = d.tet.point(d.tet.tets[4 * t + kTetFace[f][1]]);
      const double* c = d.tet.point(d.tet.tets[4 * t + kTetFace[f][2]]);
      if (a[0] == 1 && b[0] == 1 && c[0] == 1)
        area += 0.5 * std::abs((b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]));
    }
  EXPECT_DOUBLE_EQ(area, 1.0);
  long hexes_after = 0;
  for (const ElementBlock& b : d.tet.model.extra)
    hexes_after += b.gmsh_type == 5 ? b.tags.size() : 0;
  EXPECT_EQ(hexes_after, 1);
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

// Tets with negative volume (a tool of the other vertex-order convention, or a writer that mixes
// both): read and turned positive with a note, optimized, written positive; `check` of the file
// itself reports them (exit 5). Through Gmsh (.msh) and our own reader (.mesh).
TEST(RobustInputs, NegativelyOrientedTetsAreTurnedPositiveNotRefused) {
  const MeshData box = read_mesh(write_geo("neg", std::string(kBox) + "Mesh.MeshSizeMax = 0.3;\n"));
  for (const std::string ext : {".msh", ".mesh"})
    for (const int stride : {1, 2}) {
      MeshData flipped = box;
      long nb = 0;
      for (int t = 0; t < flipped.tet.nb_tets(); t += stride, ++nb)
        std::swap(flipped.tet.tets[4 * t], flipped.tet.tets[4 * t + 1]);
      const std::string path = testing::temp_dir() + "/neg" + std::to_string(stride) + ext;
      write_mesh(flipped, path);
      const MeshData d = read_mesh(path);
      EXPECT_EQ(d.model().nb_reoriented, nb) << path;
      ASSERT_FALSE(d.model().read_notes.empty()) << path;
      EXPECT_NE(d.model().read_notes.front().find("negative volume"), std::string::npos);
      EXPECT_TRUE(check_mesh(d.tet).ok) << path;
      std::string log;
      EXPECT_EQ(testing::run(testing::cli_path() + " check " + path, &log), 5) << log;
      EXPECT_NE(log.find("negative volume"), std::string::npos) << log;
      const std::string out = testing::temp_dir() + "/neg_out" + ext;
      ASSERT_EQ(testing::run(testing::cli_path() + " optimize " + path + " -o " + out +
                                 " --max-iterations 5",
                             &log),
                0)
          << log;
      EXPECT_EQ(testing::run(testing::cli_path() + " check " + out, &log), 0) << log;
    }
}

// Gmsh's view.write(..., append = true) writes the mesh again in front of the view by default
// (PostProcessing.SaveMesh = 1): every section twice, the same. Read once, with a note; a repeat
// that differs is still refused.
TEST(RobustInputs, MeshRepeatedIdenticallyBeforeAViewIsReadOnce) {
  const MeshData box = read_mesh(write_geo("rep", std::string(kBox) + "Mesh.MeshSizeMax = 0.4;\n"));
  const std::string once = testing::temp_dir() + "/rep_once.msh";
  write_mesh(box, once);
  std::ifstream in(once);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string view =
      "$NodeData\n1\n\"T\"\n1\n0\n3\n0\n1\n" + std::to_string(box.tet.nb_vertices()) + "\n";
  for (int v = 0; v < box.tet.nb_vertices(); ++v)
    view += std::to_string(v + 1) + " " + std::to_string(v) + "\n";
  view += "$EndNodeData\n";
  const std::string twice = testing::temp_dir() + "/rep_twice.msh";
  std::ofstream(twice) << text << text << view;
  const MeshData d = read_mesh(twice);
  EXPECT_EQ(d.tet.nb_tets(), box.tet.nb_tets());
  EXPECT_EQ(d.tet.nb_vertices(), box.tet.nb_vertices());
  EXPECT_EQ(d.tet.nb_tris(), box.tet.nb_tris());
  EXPECT_TRUE(check_mesh(d.tet).ok);
  EXPECT_EQ(d.model().views.size(), 1u);
  bool noted = false;
  for (const auto& n : d.model().read_notes) noted |= n.find("more than once") != std::string::npos;
  EXPECT_TRUE(noted);
  // The repeat with one node moved: ambiguous, refused.
  std::string moved = text;
  const std::size_t line = moved.find("\n0 0 0\n", moved.find("$Nodes"));
  ASSERT_NE(line, std::string::npos);
  moved.replace(line, 7, "\n0.5 0 0\n");
  const std::string differs = testing::temp_dir() + "/rep_differs.msh";
  std::ofstream(differs) << text << moved << view;
  try {
    read_mesh(differs);
    ADD_FAILURE() << "a repeat that differs was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not unique"), std::string::npos) << e.what();
  }
}

// A crack made by Gmsh's Crack plugin: two volumes whose interface is split on the crack, its
// nodes duplicated there. Each volume is optimized apart and the crack's lips keep matching: every
// pair of coincident nodes of the input is still a pair at the same place.
TEST(RobustInputs, CrackLipsKeepMatchingWhenEachVolumeIsOptimizedApart) {
  MeshData d = read_mesh(
      write_geo("crack", std::string(kBox) +
                             "Box(2) = {0,0,-1,1,1,1};\nRectangle(100) = {0.25,0.25,0,0.5,0.5};\n"
                             "BooleanFragments{ Volume{1,2}; Surface{100}; Delete; }{}\n"
                             "s() = Surface In BoundingBox{0.2,0.2,-0.01,0.8,0.8,0.01};\n"
                             "Physical Surface(1) = {s()};\nMesh.MeshSizeMax = 0.2;\nMesh 3;\n"
                             "Plugin(Crack).Dimension = 2;\nPlugin(Crack).PhysicalGroup = 1;\n"
                             "Plugin(Crack).Run;\n"));
  const StructuralDefects before = find_structural_defects(d.tet);
  ASSERT_FALSE(before.coincident_vertices.empty());
  const TetMesh input = d.tet;
  const OptimizeResult r = optimize(d, quick());
  EXPECT_TRUE(has_note(r, "each volume optimized apart"));
  EXPECT_FALSE(r.kept_input);
  expect_valid_and_no_worse(d, r);
  EXPECT_FALSE(volumes_defective_only_together(d.tet).empty());
  // The lips: each input pair of coincident nodes has both nodes, unmoved, in the output.
  std::map<std::array<double, 3>, int> at;
  for (int v = 0; v < d.tet.nb_vertices(); ++v)
    ++at[{d.tet.point(v)[0], d.tet.point(v)[1], d.tet.point(v)[2]}];
  for (const auto& [a, b] : before.coincident_vertices) {
    const double* p = input.point(a);
    EXPECT_EQ((at[{p[0], p[1], p[2]}]), 2) << "node " << a;
    (void)b;
  }
}

// Gmsh's demo pripyrtet: a square revolved about one of its sides with Recombine — prisms,
// pyramids at the axis and tets. The tets' faces on the pyramids are no missing boundary
// triangles: the output holds the input's triangles per surface, no more (stop 43: 8 more on each
// of the two end surfaces were written).
TEST(RobustInputs, TetFacesOnKeptCellsAreNotAddedAsBoundaryTriangles) {
  const MeshData g = read_mesh(
      write_geo("pripyrtet",
                "lc = 0.3;\nPoint(1) = {0,0,0,lc};\nPoint(2) = {1,0,0,lc};\n"
                "Point(3) = {1,1,0,0.5*lc};\nPoint(4) = {0,1,0,lc};\nLine(1) = {4,3};\n"
                "Line(2) = {3,2};\nLine(3) = {2,1};\nLine(4) = {1,4};\n"
                "Curve Loop(5) = {2,3,4,1};\nPlane Surface(6) = {5};\n"
                "Extrude {{0,1,0}, {0,0,0}, -Pi/4}{ Surface{6}; Layers{3,1}; Recombine; }\n"));
  ASSERT_GT(g.tet.nb_tets(), 0);
  const std::string in = testing::temp_dir() + "/pripyrtet.msh";
  write_mesh(g, in);
  auto triangles_per_surface = [](const TetMesh& m) {
    std::map<int, int> n;
    for (int f = 0; f < m.nb_tris(); ++f)
      if (!is_kept_cell_interface(m.tri_surface[f])) ++n[m.tri_surface[f]];
    return n;
  };
  const MeshData d = read_mesh(in);
  EXPECT_EQ(triangles_per_surface(d.tet), triangles_per_surface(g.tet));
  const std::string out = testing::temp_dir() + "/pripyrtet_out.msh";
  std::string log;
  ASSERT_EQ(testing::run(testing::cli_path() + " optimize " + in + " -o " + out, &log), 0) << log;
  EXPECT_EQ(triangles_per_surface(read_mesh(out).tet), triangles_per_surface(g.tet));
}

}  // namespace
}  // namespace cvtmesh
