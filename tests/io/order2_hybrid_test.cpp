// Order-2 hybrid meshes (tutorial t3 at -order 2: prism18 and tet10): the order-2 prisms and
// their quadrangles are kept verbatim with all their nodes, every node of theirs fixed; the tets
// are optimized; the tet10s that share an edge with a prism keep the prism's node there (the
// mesh stays conforming); `check` passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "tests/io/gmsh_dump.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

using testing::gmsh_dump;
using testing::GmshDump;

// Tets on top of one layer of prisms (extruded with Recombine), conforming, at order 2.
const char* kPrismLayer2 =
    "Point(1)={0,0,0,0.3};Point(2)={1,0,0,0.3};Point(3)={1,1,0,0.3};Point(4)={0,1,0,0.3};\n"
    "Line(1)={1,2};Line(2)={2,3};Line(3)={3,4};Line(4)={4,1};\n"
    "Curve Loop(1)={1,2,3,4};Plane Surface(1)={1};\n"
    "a[] = Extrude{0,0,0.2}{Surface{1}; Layers{2}; Recombine;};\n"
    "b[] = Extrude{0,0,0.8}{Surface{a[0]};};\nMesh.ElementOrder = 2;\n";

// Gmsh's prism18 corner pairs of its 9 mid-edge nodes (nodes 6..14).
const int kPrismEdges[9][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 4},
                               {2, 5}, {3, 4}, {3, 5}, {4, 5}};
// Gmsh's tet10 corner pairs of its 6 mid-edge nodes (nodes 4..9).
const int kTetEdges[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};

TEST(Order2Hybrid, PrismsAreKeptWithTheirNodesAndTheTetsStayConformingToThem) {
  const std::string dir = testing::temp_dir();
  const std::string geo = dir + "/prisms2.geo", in = dir + "/prisms2.msh",
                    out = dir + "/prisms2_opt.msh";
  std::ofstream(geo) << kPrismLayer2;
  std::string log;
  ASSERT_EQ(testing::run("gmsh -v 0 -3 " + geo + " -o " + in, &log), 0) << log;
  const GmshDump a = gmsh_dump(in);
  std::map<int, long> types;
  for (const auto& [tag, e] : a.elements) ++types[std::get<0>(e)];
  ASSERT_GT(types[13], 10) << "no prism18: not the case under test";
  ASSERT_GT(types[11], 10) << "no tet10: not the case under test";
  ASSERT_EQ(testing::run(testing::cli_path() + " optimize " + in + " -o " + out, &log), 0) << log;
  EXPECT_EQ(testing::run(testing::cli_path() + " check " + out, &log), 0) << log;
  const GmshDump b = gmsh_dump(out);
  // Every prism18 and quad9 kept, every node of theirs where it was.
  std::set<std::size_t> prism_nodes;
  long kept = 0;
  for (const auto& [tag, e] : a.elements) {
    const int type = std::get<0>(e);
    if (type != 13 && type != 10) continue;
    const auto it = b.elements.find(tag);
    ASSERT_NE(it, b.elements.end()) << "element " << tag << " lost";
    EXPECT_EQ(it->second, e);
    ++kept;
    for (std::size_t n : std::get<3>(e)) prism_nodes.insert(n);
  }
  EXPECT_EQ(kept, types[13] + types[10]);
  for (std::size_t n : prism_nodes) {
    ASSERT_TRUE(b.nodes.count(n)) << "node " << n << " lost";
    const auto& p = a.nodes.at(n);
    const auto& q = b.nodes.at(n);
    EXPECT_EQ(std::get<0>(p), std::get<0>(q));
    EXPECT_EQ(std::get<1>(p), std::get<1>(q));
    EXPECT_EQ(std::get<2>(p), std::get<2>(q));
  }
  // Conforming: a tet10 edge that is a prism18 edge has the prism's node on it.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> prism_mid;
  for (const auto& [tag, e] : b.elements)
    if (std::get<0>(e) == 13) {
      const auto& n = std::get<3>(e);
      for (int k = 0; k < 9; ++k)
        prism_mid[std::minmax(n[kPrismEdges[k][0]], n[kPrismEdges[k][1]])] = n[6 + k];
    }
  long shared = 0;
  for (const auto& [tag, e] : b.elements) {
    if (std::get<0>(e) != 11) continue;
    const auto& n = std::get<3>(e);
    for (int k = 0; k < 6; ++k) {
      const auto it = prism_mid.find(std::minmax(n[kTetEdges[k][0]], n[kTetEdges[k][1]]));
      if (it == prism_mid.end()) continue;
      ++shared;
      EXPECT_EQ(n[4 + k], it->second) << "tet10 " << tag << " is not conforming to the prisms";
    }
  }
  EXPECT_GT(shared, 0) << "no tet10 meets a prism18: not the case under test";
}

}  // namespace
}  // namespace cvtmesh
