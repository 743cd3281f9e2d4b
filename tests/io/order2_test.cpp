// Order-2 meshes (tet10, tri6, line3; issue 14; in 2D tri6 and line3): read as their corner mesh,
// optimized, written back as order 2 with the mid-edge nodes re-placed: kept where the edge and
// its corners are the input's, on the CAD for a CAD model, straight in the interior; no inverted
// tet10 or tri6.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <gmsh.h>

#include "core/geometry/tet10_positive.h"
#include "core/geometry/tri6_positive.h"
#include "core/io/place_mid_edge_nodes.h"
#include "core/io/gmsh_session.h"
#include "core/io/read_mesh.h"
#include "core/io/write_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/util/error.h"
#include "tests/io/gmsh_dump.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

using testing::gmsh_dump;
using testing::GmshDump;
using testing::run;

// Gmsh's node order of a tet10's mid-edge nodes: (0,1) (1,2) (2,0) (3,0) (3,2) (3,1).
const int kGmshTet10[6][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};

std::array<double, 3> xyz_of(const GmshDump& d, std::size_t tag) {
  const auto& n = d.nodes.at(tag);
  return {std::get<0>(n), std::get<1>(n), std::get<2>(n)};
}

// Counts of elements by Gmsh type.
std::map<int, int> types_of(const GmshDump& d) {
  std::map<int, int> t;
  for (const auto& [tag, e] : d.elements) ++t[std::get<0>(e)];
  return t;
}

// Every tet10 positive (tet10_positive, on the nodes as written).
int nb_not_positive(const GmshDump& d) {
  int bad = 0;
  for (const auto& [tag, e] : d.elements) {
    if (std::get<0>(e) != 11) continue;
    const auto& nd = std::get<3>(e);
    std::array<std::array<double, 3>, 10> p;
    for (int i = 0; i < 10; ++i) p[i] = xyz_of(d, nd[i]);
    const double* c[4] = {p[0].data(), p[1].data(), p[2].data(), p[3].data()};
    const double* m[6];
    // tet10_positive's edge order from Gmsh's.
    for (int k = 0; k < 6; ++k)
      for (int g = 0; g < 6; ++g) {
        const int a = kGmshTet10[g][0], b = kGmshTet10[g][1];
        if ((a == kTet10Edge[k][0] && b == kTet10Edge[k][1]) ||
            (b == kTet10Edge[k][0] && a == kTet10Edge[k][1]))
          m[k] = p[4 + g].data();
      }
    bad += !tet10_positive(c, m);
  }
  return bad;
}

// Largest distance of an order-2 element's mid-edge node classified in the interior (dim
// `interior`) from its edge's straight midpoint, relative to the edge length: Gmsh type 11 (tet10,
// its 6 edge nodes after the 4 corners) or 9 (tri6, 3 after 3).
double max_offset(const GmshDump& d, int type, int interior) {
  static const int kGmshTri6[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  const int nc = type == 11 ? 4 : 3, ne = type == 11 ? 6 : 3;
  const int(*edge)[2] = type == 11 ? kGmshTet10 : kGmshTri6;
  double worst = 0;
  for (const auto& [tag, e] : d.elements) {
    if (std::get<0>(e) != type) continue;
    const auto& nd = std::get<3>(e);
    for (int g = 0; g < ne; ++g) {
      if (std::get<3>(d.nodes.at(nd[nc + g])) != interior) continue;
      const auto a = xyz_of(d, nd[edge[g][0]]), b = xyz_of(d, nd[edge[g][1]]);
      const auto m = xyz_of(d, nd[nc + g]);
      double off = 0, len = 0;
      for (int k = 0; k < 3; ++k) {
        off += std::pow(m[k] - 0.5 * (a[k] + b[k]), 2);
        len += std::pow(a[k] - b[k], 2);
      }
      worst = std::max(worst, std::sqrt(off / len));
    }
  }
  return worst;
}

// The same for the tet10s' nodes in the volume.
double max_interior_offset(const GmshDump& d) {
  return max_offset(d, 11, 3);
}

std::string write_geo(const std::string& dir, const std::string& name, const std::string& body) {
  const std::string path = dir + "/" + name;
  std::ofstream(path) << body;
  return path;
}

const char* kBox =
    "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 0.6};\n"
    "Physical Volume(\"solid\", 7) = {1};\nPhysical Surface(\"skin\", 8) = {1, 2, 3, 4, 5, 6};\n"
    "Mesh.MeshSizeMax = 0.25;\nMesh.ElementOrder = 2;\n";
const char* kBall =
    "SetFactory(\"OpenCASCADE\");\nSphere(1) = {0.1, 0.2, 0.3, 1};\n"
    "Mesh.MeshSizeMax = 0.4;\nMesh.ElementOrder = 2;\n";

// An order-2 box from the gmsh executable, as a user brings it.
std::string order2_box_msh(const std::string& dir) {
  const std::string geo = write_geo(dir, "box.geo", kBox);
  const std::string msh = dir + "/box2.msh";
  std::string log;
  EXPECT_EQ(run("gmsh -v 0 -3 " + geo + " -o " + msh, &log), 0) << log;
  return msh;
}

TEST(Order2, ReadAsCornerMeshAndConvertKeepsEverything) {
  const std::string dir = testing::temp_dir();
  const std::string msh = order2_box_msh(dir);
  const MeshData d = read_mesh(msh);
  ASSERT_EQ(d.dim, 3);
  EXPECT_EQ(d.model().high_order.order, 2);
  EXPECT_TRUE(check_mesh(d.tet).ok);
  // The mesh's vertices are the corners: every one is used by a tet.
  std::set<int> used(d.tet.tets.begin(), d.tet.tets.end());
  EXPECT_EQ(static_cast<int>(used.size()), d.tet.nb_vertices());
  EXPECT_GT(d.model().high_order.tags.size(), 0u);
  // convert: the same Gmsh model back (types, tags, nodes, groups).
  const std::string copy = dir + "/copy.msh";
  std::string log;
  ASSERT_EQ(run(testing::cli_path() + " convert " + msh + " " + copy, &log), 0) << log;
  const GmshDump a = gmsh_dump(msh), b = gmsh_dump(copy);
  EXPECT_EQ(a.groups, b.groups);
  EXPECT_TRUE(a.nodes == b.nodes) << "node tags, coordinates or classification differ";
  EXPECT_TRUE(a.elements == b.elements) << "elements differ";
  // stats on an order-2 file.
  EXPECT_EQ(run(testing::cli_path() + " stats " + msh, &log), 0) << log;
}

TEST(Order2, OptimizeDiscreteBoxStaysOrder2WithStraightInteriorNodes) {
  const std::string dir = testing::temp_dir();
  const std::string msh = order2_box_msh(dir);
  const std::string out = dir + "/opt.msh";
  std::string log;
  ASSERT_EQ(run(testing::cli_path() + " optimize " + msh + " -o " + out, &log), 0) << log;
  EXPECT_NE(log.find("order-2 mesh:"), std::string::npos) << log;
  EXPECT_EQ(run(testing::cli_path() + " check " + out, &log), 0) << log;
  EXPECT_EQ(run(testing::cli_path() + " stats " + out, &log), 0) << log;
  const GmshDump in = gmsh_dump(msh), o = gmsh_dump(out);
  // Only order-2 simplices (and points) in, the same out.
  std::set<int> tin, tout;
  for (const auto& [t, n] : types_of(in)) tin.insert(t);
  for (const auto& [t, n] : types_of(o)) tout.insert(t);
  EXPECT_EQ(tin, tout);
  EXPECT_EQ(tout.count(4) + tout.count(2) + tout.count(1), 0u);
  EXPECT_EQ(in.groups, o.groups);
  EXPECT_EQ(nb_not_positive(o), 0);
  // The interior moved: its mid-edge nodes are straight midpoints of the new edges.
  EXPECT_LT(max_interior_offset(o), 1e-12);
  bool moved = false;
  for (const auto& [tag, n] : o.nodes)
    if (std::get<3>(n) == 3 && in.nodes.count(tag) && in.nodes.at(tag) != n) moved = true;
  EXPECT_TRUE(moved) << "the optimizer moved no interior node: the test shows nothing";
}

TEST(Order2, OccBallMidEdgeBoundaryNodesOnTheSphere) {
  const std::string dir = testing::temp_dir();
  const std::string geo = write_geo(dir, "ball.geo", kBall);
  for (const std::string flags : {"", " --fix-boundary"}) {
    const std::string out = dir + "/ball_opt.msh";
    std::string log;
    ASSERT_EQ(run(testing::cli_path() + " optimize " + geo + flags + " -o " + out, &log), 0) << log;
    EXPECT_NE(log.find("order-2 mesh:"), std::string::npos) << log;
    EXPECT_EQ(run(testing::cli_path() + " check " + out, &log), 0) << log;
    const GmshDump o = gmsh_dump(out);
    EXPECT_EQ(nb_not_positive(o), 0);
    int on_surface = 0;
    double worst = 0;
    for (const auto& [tag, e] : o.elements) {
      if (std::get<0>(e) != 9) continue;  // tri6 on the sphere
      const auto& nd = std::get<3>(e);
      for (int k = 3; k < 6; ++k) {
        const auto p = xyz_of(o, nd[k]);
        const double r =
            std::sqrt(std::pow(p[0] - 0.1, 2) + std::pow(p[1] - 0.2, 2) + std::pow(p[2] - 0.3, 2));
        worst = std::max(worst, std::abs(r - 1));
        ++on_surface;
      }
    }
    EXPECT_GT(on_surface, 0);
    EXPECT_LT(worst, 1e-9) << flags;
    EXPECT_LT(max_interior_offset(o), 1e-12);
  }
}

// Gmsh's tutorials t2 and t5 at `-order 2`: a physical volume and no physical surface, so the
// file holds tet10s and no tri6 on their boundary or interface; the reader adds the missing
// facets (their mid-edge nodes are the tets'), as it does for a linear file.
TEST(Order2, PhysicalVolumesOnlyTwoRegionsReadCheckedAndOptimized) {
  const std::string dir = testing::temp_dir();
  const std::string geo = write_geo(
      dir, "two.geo",
      "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\nBox(2) = {1, 0, 0, 1, 1, 1};\n"
      "BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n"
      "Physical Volume(\"left\", 1) = {1};\nPhysical Volume(\"right\", 2) = {2};\n"
      "Mesh.MeshSizeMax = 0.3;\nMesh.ElementOrder = 2;\n");
  const std::string msh = dir + "/two2.msh";
  std::string log;
  ASSERT_EQ(run("gmsh -v 0 -3 " + geo + " -o " + msh, &log), 0) << log;
  const GmshDump in = gmsh_dump(msh);
  ASSERT_EQ(types_of(in).count(9), 0u) << "the file holds tri6: not the case under test";
  const MeshData d = read_mesh(msh);
  EXPECT_EQ(d.model().high_order.order, 2);
  EXPECT_TRUE(check_mesh(d.tet).ok);
  EXPECT_EQ(run(testing::cli_path() + " check " + msh, &log), 0) << log;
  const std::string out = dir + "/two_opt.msh";
  ASSERT_EQ(run(testing::cli_path() + " optimize " + msh + " -o " + out, &log), 0) << log;
  EXPECT_EQ(run(testing::cli_path() + " check " + out, &log), 0) << log;
  const GmshDump o = gmsh_dump(out);
  // The file's blocks and groups, nothing added: tet10 only (no linear element, no tri6).
  std::set<int> tin, tout;
  for (const auto& [t, n] : types_of(in)) tin.insert(t);
  for (const auto& [t, n] : types_of(o)) tout.insert(t);
  EXPECT_EQ(tin, tout);
  EXPECT_EQ(in.groups, o.groups);
  EXPECT_EQ(nb_not_positive(o), 0);
}

TEST(Order2, CheckReportsAnInvertedTet10) {
  const std::string dir = testing::temp_dir();
  const std::string msh = order2_box_msh(dir);
  const std::string bad = dir + "/bad.msh";
  {
    // Move one interior mid-edge node of a tet10 far through the tet.
    GmshSession session;
    gmsh::open(msh);
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(11, tags, nodes);
    ASSERT_FALSE(tags.empty());
    std::vector<std::size_t> interior;
    std::vector<double> ixyz, ipar;
    gmsh::model::mesh::getNodes(interior, ixyz, ipar, 3, -1, false, false);
    const std::set<std::size_t> inside(interior.begin(), interior.end());
    bool moved = false;
    for (std::size_t e = 0; e < tags.size() && !moved; ++e) {
      if (!inside.count(nodes[10 * e + 4])) continue;
      std::vector<double> c, p, opposite, q;
      gmsh::model::mesh::getNode(nodes[10 * e + 4], c, p);
      gmsh::model::mesh::getNode(nodes[10 * e + 3], opposite, q);
      for (int k = 0; k < 3; ++k) c[k] += 1.5 * (opposite[k] - c[k]);
      gmsh::model::mesh::setNode(nodes[10 * e + 4], c, {});
      moved = true;
    }
    ASSERT_TRUE(moved);
    gmsh::write(bad);
    gmsh::model::remove();
  }
  std::string log;
  EXPECT_EQ(run(testing::cli_path() + " check " + msh, &log), 0) << log;
  EXPECT_NE(log.find("order 2"), std::string::npos) << log;
  EXPECT_EQ(run(testing::cli_path() + " check " + bad, &log), 5) << log;
  EXPECT_NE(log.find("order-2 tetrahedra are not positive"), std::string::npos) << log;
}

// --- 2D: tri6 and line3 in the plane z = const.

const char* kDisk =
    "SetFactory(\"OpenCASCADE\");\nDisk(1) = {0.1, 0.2, 0, 1};\n"
    "Mesh.MeshSizeMax = 0.15;\nMesh.ElementOrder = 2;\n";

// An order-2 disk from the gmsh executable, as a user brings it.
std::string order2_disk_msh(const std::string& dir) {
  const std::string geo = write_geo(dir, "disk.geo", kDisk);
  const std::string msh = dir + "/disk2.msh";
  std::string log;
  EXPECT_EQ(run("gmsh -v 0 -2 " + geo + " -o " + msh, &log), 0) << log;
  return msh;
}

// Distance of p from the disk's circle (centre (0.1, 0.2), radius 1) plus dx, dy.
double off_circle(const double* p, double dx = 0, double dy = 0) {
  return std::abs(std::hypot(p[0] - 0.1 - dx, p[1] - 0.2 - dy) - 1);
}

// Every tri6 positive (tri6_positive, on the nodes as written; a clockwise one turned over).
int nb_tri6_not_positive(const GmshDump& d) {
  int bad = 0;
  for (const auto& [tag, e] : d.elements) {
    if (std::get<0>(e) != 9) continue;
    const auto& nd = std::get<3>(e);
    std::array<std::array<double, 3>, 6> p;
    for (int i = 0; i < 6; ++i) p[i] = xyz_of(d, nd[i]);
    const double* c[3] = {p[0].data(), p[1].data(), p[2].data()};
    const double* m[3] = {p[3].data(), p[4].data(), p[5].data()};  // (0,1) (1,2) (2,0)
    const double area =
        (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
    if (area < 0) {  // corners 0 2 1: edges (0,2) (2,1) (1,0)
      std::swap(c[1], c[2]);
      const double* m01 = m[0];
      m[0] = m[2];
      m[2] = m01;
    }
    bad += !tri6_positive(c, m);
  }
  return bad;
}

// The same for the tri6s' nodes on the surface (a planar mesh's interior).
double max_planar_interior_offset(const GmshDump& d) {
  return max_offset(d, 9, 2);
}

TEST(Order2, PlanarReadAsCornerMeshAndConvertKeepsEveryNode) {
  const std::string dir = testing::temp_dir();
  const std::string msh = order2_disk_msh(dir);
  const MeshData d = read_mesh(msh);
  ASSERT_EQ(d.dim, 2);
  EXPECT_EQ(d.model().high_order.order, 2);
  EXPECT_TRUE(check_mesh(d.tri).ok);
  // The mesh's vertices are the corners: every one is used by a triangle.
  std::set<int> used(d.tri.tris.begin(), d.tri.tris.end());
  EXPECT_EQ(static_cast<int>(used.size()), d.tri.nb_vertices());
  // One mid-edge node per edge: E = V + T - 1 for a disk (Euler).
  EXPECT_EQ(static_cast<long>(d.model().high_order.tags.size()),
            d.tri.nb_vertices() + d.tri.nb_tris() - 1);
  // convert: the same Gmsh model back (types, tags, nodes, groups).
  const std::string copy = dir + "/copy.msh";
  std::string log;
  ASSERT_EQ(run(testing::cli_path() + " convert " + msh + " " + copy, &log), 0) << log;
  const GmshDump a = gmsh_dump(msh), b = gmsh_dump(copy);
  EXPECT_EQ(a.groups, b.groups);
  EXPECT_TRUE(a.nodes == b.nodes) << "node tags, coordinates or classification differ";
  EXPECT_TRUE(a.elements == b.elements) << "elements differ";
  EXPECT_GT(types_of(b)[9], 0);
  // stats and check on an order-2 file.
  EXPECT_EQ(run(testing::cli_path() + " stats " + msh, &log), 0) << log;
  EXPECT_EQ(run(testing::cli_path() + " check " + copy, &log), 0) << log;
  EXPECT_NE(log.find("ok (order 2"), std::string::npos) << log;
}

// The disk optimized from its .msh (discrete) and from its .geo (CAD): order 2 out, tri6 and
// line3 only, interior mid-edge nodes straight, boundary ones on the circle (the input's, kept:
// the 2D boundary does not move).
TEST(Order2, PlanarDiskOptimizedStaysOrder2OnTheCircle) {
  const std::string dir = testing::temp_dir();
  const std::string msh = order2_disk_msh(dir);
  const std::string geo = dir + "/disk.geo";
  const GmshDump in = gmsh_dump(msh);
  for (const std::string& src : {msh, geo}) {
    const std::string out = dir + "/disk_opt.msh";
    std::string log;
    ASSERT_EQ(run(testing::cli_path() + " optimize " + src + " -o " + out, &log), 0) << log;
    EXPECT_NE(log.find("order-2 mesh:"), std::string::npos) << log;
    EXPECT_EQ(run(testing::cli_path() + " check " + out, &log), 0) << log;
    EXPECT_NE(log.find("ok (order 2"), std::string::npos) << log;
    const GmshDump o = gmsh_dump(out);
    std::map<int, int> types = types_of(o);
    EXPECT_GT(types[9], 0) << src;
    EXPECT_GT(types[8], 0) << src;
    types.erase(9);
    types.erase(8);
    types.erase(15);  // the circle's point
    EXPECT_TRUE(types.empty()) << src << ": element types other than tri6, line3 and points";
    EXPECT_EQ(nb_tri6_not_positive(o), 0) << src;
    EXPECT_LT(max_planar_interior_offset(o), 1e-12) << src;
    int on_circle = 0;
    double worst = 0;
    for (const auto& [tag, e] : o.elements) {
      if (std::get<0>(e) != 8) continue;
      const auto p = xyz_of(o, std::get<3>(e)[2]);
      worst = std::max(worst, off_circle(p.data()));
      EXPECT_EQ(p[2], 0.0);
      ++on_circle;
    }
    EXPECT_GT(on_circle, 0) << src;
    EXPECT_LT(worst, 1e-9) << src;
    if (src == msh) {
      // The boundary's mid-edge nodes are the input's (tag and position).
      for (const auto& [tag, e] : o.elements)
        if (std::get<0>(e) == 8)
          EXPECT_EQ(o.nodes.at(std::get<3>(e)[2]), in.nodes.at(std::get<3>(e)[2]));
      bool moved = false;
      for (const auto& [tag, n] : o.nodes)
        if (std::get<3>(n) == 2 && in.nodes.count(tag) && in.nodes.at(tag) != n) moved = true;
      EXPECT_TRUE(moved) << "the optimizer moved no interior node: the test shows nothing";
    }
  }
}

// The rules of place_mid_edge_nodes on a planar mesh, one by one: kept, the input's offset
// carried, on the geometry (a projector), straight, and the fallback of an inverted tri6.
TEST(Order2, PlanarPlacementRules) {
  const std::string dir = testing::temp_dir();
  MeshData d = read_mesh(order2_disk_msh(dir));
  ASSERT_EQ(d.dim, 2);
  const int nb_boundary = d.tri.nb_edges();
  const int nb_nodes = static_cast<int>(d.model().high_order.tags.size());
  ASSERT_GT(nb_boundary, 0);
  // Unmoved: every node the input's.
  MidEdgePlacement p = place_mid_edge_nodes(d.tri);
  EXPECT_EQ(p.nb_kept, nb_nodes);
  EXPECT_EQ(p.nb_invalid, 0);
  // Translated: no edge is the input's any more; the boundary's nodes carry their offset (on the
  // translated circle), the interior's are straight.
  const double dx = 0.25, dy = -0.5;
  for (int v = 0; v < d.tri.nb_vertices(); ++v) {
    d.tri.xy[2 * v] += dx;
    d.tri.xy[2 * v + 1] += dy;
  }
  p = place_mid_edge_nodes(d.tri);
  EXPECT_EQ(p.nb_kept, 0);
  EXPECT_EQ(p.nb_curved, nb_boundary);
  EXPECT_EQ(p.nb_straight, nb_nodes - nb_boundary);
  EXPECT_EQ(p.nb_fallback + p.nb_invalid, 0);
  for (int k = 0; k < nb_nodes; ++k) {
    const double* x = &p.xyz[3 * k];
    EXPECT_EQ(x[2], d.tri.z0);
    if (p.where[k].dim == 1) EXPECT_LT(off_circle(x, dx, dy), 1e-12);
  }
  // A projector (here onto the translated circle) takes the boundary's nodes, and only those.
  int asked_off_curve = 0;
  auto onto_circle = [&](double shrink) {
    return [&, shrink](int dim, int, const double* q, double* out) {
      asked_off_curve += dim != 1;
      const double cx = 0.1 + dx, cy = 0.2 + dy, r = std::hypot(q[0] - cx, q[1] - cy);
      out[0] = cx + shrink * (q[0] - cx) / r;
      out[1] = cy + shrink * (q[1] - cy) / r;
      out[2] = q[2] + 1;  // the plane wins
      return true;
    };
  };
  p = place_mid_edge_nodes(d.tri, onto_circle(1.0));
  EXPECT_EQ(asked_off_curve, 0);
  EXPECT_EQ(p.nb_cad, nb_boundary);
  EXPECT_EQ(p.nb_fallback + p.nb_invalid, 0);
  for (int k = 0; k < nb_nodes; ++k)
    if (p.where[k].dim == 1) {
      EXPECT_LT(off_circle(&p.xyz[3 * k], dx, dy), 1e-12);
      EXPECT_EQ(p.xyz[3 * k + 2], d.tri.z0);
    }
  // A projection that would invert the boundary's triangles (nodes pulled to radius 0.5):
  // checked as placed, they are invalid; with the fallback, straight and valid.
  p = place_mid_edge_nodes(d.tri, onto_circle(0.5), false);
  EXPECT_GT(p.nb_invalid, 0);
  p = place_mid_edge_nodes(d.tri, onto_circle(0.5));
  EXPECT_EQ(p.nb_fallback, nb_boundary);
  EXPECT_EQ(p.nb_cad, 0);
  EXPECT_EQ(p.nb_invalid, 0);
}

TEST(Order2, PlanarCheckReportsAnInvertedTri6) {
  const std::string dir = testing::temp_dir();
  const std::string msh = order2_disk_msh(dir);
  const std::string bad = dir + "/bad.msh", off_plane = dir + "/off_plane.msh";
  {
    // Move one interior mid-edge node of a tri6 past the opposite corner.
    GmshSession session;
    gmsh::open(msh);
    std::vector<std::size_t> tags, nodes;
    gmsh::model::mesh::getElementsByType(9, tags, nodes);
    ASSERT_FALSE(tags.empty());
    std::vector<std::size_t> interior;
    std::vector<double> ixyz, ipar;
    gmsh::model::mesh::getNodes(interior, ixyz, ipar, 2, -1, false, false);
    const std::set<std::size_t> inside(interior.begin(), interior.end());
    bool moved = false;
    for (std::size_t e = 0; e < tags.size() && !moved; ++e) {
      if (!inside.count(nodes[6 * e + 3])) continue;
      std::vector<double> c, p, opposite, q;
      gmsh::model::mesh::getNode(nodes[6 * e + 3], c, p);
      gmsh::model::mesh::getNode(nodes[6 * e + 2], opposite, q);
      const std::vector<double> original = c;
      for (int k = 0; k < 2; ++k) c[k] += 1.5 * (opposite[k] - c[k]);
      gmsh::model::mesh::setNode(nodes[6 * e + 3], c, {});
      moved = true;
      gmsh::write(bad);
      // The same node out of the plane instead: refused as not planar.
      c = original;
      c[2] += 0.1;
      gmsh::model::mesh::setNode(nodes[6 * e + 3], c, {});
      gmsh::write(off_plane);
    }
    ASSERT_TRUE(moved);
    gmsh::model::remove();
  }
  try {
    read_mesh(off_plane);
    FAIL() << "a tri6 with a mid-edge node off the plane was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not in the plane"), std::string::npos) << e.what();
  }
  std::string log;
  EXPECT_EQ(run(testing::cli_path() + " check " + msh, &log), 0) << log;
  EXPECT_NE(log.find("order 2"), std::string::npos) << log;
  EXPECT_EQ(run(testing::cli_path() + " check " + bad, &log), 5) << log;
  EXPECT_NE(log.find("order-2 triangles are not positive"), std::string::npos) << log;
}

// Order-2 quadrangles (t11 at -order 2) stay refused, by the file's and the type's name.
TEST(Order2, PlanarQuadranglesAreRefusedByName) {
  const std::string dir = testing::temp_dir();
  const std::string geo = write_geo(
      dir, "sq.geo",
      "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 1, 1};\nMesh.MeshSizeMax = 0.3;\n"
      "Recombine Surface{1};\nMesh.ElementOrder = 2;\n");
  try {
    read_mesh(geo);
    FAIL() << "an order-2 quadrangle mesh was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("sq.geo"), std::string::npos) << m;
    EXPECT_NE(m.find("Quadrilateral"), std::string::npos) << m;
    EXPECT_NE(m.find("Recombine"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace cvtmesh
