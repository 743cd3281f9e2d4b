// Surface meshes in space (triangles on surfaces that bound no volume): read, optimized on their
// surfaces (core/boundary/optimize_surface_mesh.h through optimize()), checked and written with
// everything the file held. The properties are checked independently of the optimizer: distances
// to the input triangulation by brute force, orientation against the exact sphere's normal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include "core/boundary/discrete_boundary.h"
#include "core/boundary/flip_surface_edges.h"
#include "core/io/read_mesh.h"
#include "core/io/write_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/check_surface_mesh.h"
#include "core/pipeline/optimize.h"
#include "core/quality/quality.h"
#include "core/quality/quality_stats.h"
#include "core/quality/worse_than.h"
#include "tests/io/gmsh_dump.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

using testing::run;

// A graded octant of the unit sphere (open: it bounds no volume), its rim curves and a corner in
// physical groups.
const char* kOctant =
    "Point(1) = {0, 0, 0, 0.1};\nPoint(2) = {1, 0, 0, 0.04};\nPoint(3) = {0, 1, 0, 0.15};\n"
    "Point(4) = {0, 0, 1, 0.25};\nCircle(1) = {2, 1, 3};\nCircle(2) = {3, 1, 4};\n"
    "Circle(3) = {4, 1, 2};\nCurve Loop(1) = {1, 2, 3};\nSurface(1) = {1};\n"
    "Physical Surface(\"octant\", 7) = {1};\nPhysical Curve(\"rim\", 8) = {1, 2, 3};\n"
    "Physical Point(\"corner\", 9) = {2};\n";

std::string mesh_geo(const std::string& dir, const std::string& body, const std::string& name) {
  const std::string geo = dir + "/" + name + ".geo", msh = dir + "/" + name + ".msh";
  std::ofstream(geo) << body;
  std::string log;
  EXPECT_EQ(run("gmsh -v 0 -2 " + geo + " -o " + msh, &log), 0) << log;
  return msh;
}

double point_segment_distance(const double* p, const double* a, const double* b) {
  double ab[3], ap[3], l2 = 0, t = 0;
  for (int k = 0; k < 3; ++k) {
    ab[k] = b[k] - a[k];
    ap[k] = p[k] - a[k];
    l2 += ab[k] * ab[k];
    t += ab[k] * ap[k];
  }
  t = l2 > 0 ? std::clamp(t / l2, 0.0, 1.0) : 0;
  double d2 = 0;
  for (int k = 0; k < 3; ++k) d2 += (ap[k] - t * ab[k]) * (ap[k] - t * ab[k]);
  return std::sqrt(d2);
}

// Distance from p to triangle (a, b, c): to its plane if the foot is inside, else to its edges.
double point_triangle_distance(const double* p, const double* a, const double* b, const double* c) {
  double u[3], v[3], w[3], n[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
    w[k] = p[k] - a[k];
  }
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (nn > 0) {
    const double s = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]) / nn;
    double q[3];
    for (int k = 0; k < 3; ++k) q[k] = p[k] - s * n[k];
    // Barycentric signs of the foot q.
    auto side = [&](const double* x, const double* y) {
      double e[3], f[3];
      for (int k = 0; k < 3; ++k) {
        e[k] = y[k] - x[k];
        f[k] = q[k] - x[k];
      }
      return (e[1] * f[2] - e[2] * f[1]) * n[0] + (e[2] * f[0] - e[0] * f[2]) * n[1] +
             (e[0] * f[1] - e[1] * f[0]) * n[2];
    };
    if (side(a, b) >= 0 && side(b, c) >= 0 && side(c, a) >= 0) return std::abs(s) * std::sqrt(nn);
  }
  return std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                   point_segment_distance(p, c, a)});
}

double distance_to_triangles(const double* p, const TetMesh& m) {
  double d = std::numeric_limits<double>::infinity();
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* t = &m.tris[3 * f];
    d = std::min(d, point_triangle_distance(p, m.point(t[0]), m.point(t[1]), m.point(t[2])));
  }
  return d;
}

TEST(SurfaceMesh3, CurvedOpenSurfaceIsOptimizedOnItsSurfaceNeverWorse) {
  const std::string dir = testing::temp_dir();
  const std::string msh = mesh_geo(dir, kOctant, "octant");
  MeshData d = read_mesh(msh);
  ASSERT_EQ(d.dim, 3);
  ASSERT_TRUE(is_surface_mesh(d.tet));
  ASSERT_TRUE(check_mesh(d.tet).ok);
  const TetMesh input = d.tet;
  const OptimizeResult r = optimize(d, OptimizeOptions{});
  const TetMesh& out = d.tet;
  ASSERT_FALSE(r.kept_input) << (r.notes.empty() ? "" : r.notes.back());
  // Never worse, and better: a graded Gmsh mesh of a curved patch is not max-min optimal.
  EXPECT_GE(r.after.min_angle, r.before.min_angle);
  EXPECT_GE(r.after.q_min, r.before.q_min);
  EXPECT_LE(r.after.max_angle, r.before.max_angle);
  EXPECT_GT(r.after.q_min, r.before.q_min);
  EXPECT_EQ(r.after.nb_elements, r.before.nb_elements);
  ASSERT_EQ(out.nb_vertices(), input.nb_vertices());
  EXPECT_EQ(out.node_tags, input.node_tags);
  EXPECT_TRUE(check_mesh(out).ok);
  EXPECT_TRUE(folded_triangle_pairs(out).empty());
  // Within the bound of the input triangulation: every vertex and every triangle's centroid.
  ASSERT_GT(r.hausdorff_tolerance, 0);
  for (int v = 0; v < out.nb_vertices(); ++v)
    EXPECT_LE(distance_to_triangles(out.point(v), input), r.hausdorff_tolerance) << v;
  for (int f = 0; f < out.nb_tris(); ++f) {
    const int* t = &out.tris[3 * f];
    double c[3];
    for (int k = 0; k < 3; ++k)
      c[k] = (out.point(t[0])[k] + out.point(t[1])[k] + out.point(t[2])[k]) / 3;
    EXPECT_LE(distance_to_triangles(c, input), r.hausdorff_tolerance) << f;
  }
  // No triangle turned over: each faces the way the input's did, against the sphere's normal.
  auto facing = [](const TetMesh& m, int f) {
    const int* t = &m.tris[3 * f];
    const double *a = m.point(t[0]), *b = m.point(t[1]), *c = m.point(t[2]);
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
    return n[0] * (a[0] + b[0] + c[0]) + n[1] * (a[1] + b[1] + c[1]) + n[2] * (a[2] + b[2] + c[2]);
  };
  const bool outwards = facing(input, 0) > 0;
  for (int f = 0; f < out.nb_tris(); ++f) EXPECT_EQ(facing(out, f) > 0, outwards) << f;
  // The rim's nodes stay on their curves (the coordinate planes), the corners where they were.
  for (int v = 0; v < out.nb_vertices(); ++v) {
    const VertexClass c = out.vclass[v];
    const double* p = out.point(v);
    if (c.dim == 0) {
      for (int k = 0; k < 3; ++k) EXPECT_EQ(p[k], input.point(v)[k]);
    } else if (c.dim == 1) {
      const int plane = c.entity == 1 ? 2 : c.entity == 2 ? 0 : 1;  // z = 0, x = 0, y = 0
      EXPECT_NEAR(p[plane], 0, 1e-12) << v;
    }
  }
  // Written: nothing of the file lost, and our own check accepts it.
  const std::string out_msh = dir + "/octant_opt.msh";
  write_mesh(d, out_msh);
  const testing::GmshDump a = testing::gmsh_dump(msh), b = testing::gmsh_dump(out_msh);
  EXPECT_EQ(a.groups, b.groups);
  EXPECT_EQ(a.entities.size(), b.entities.size());
  auto census = [](const testing::GmshDump& g) {
    std::map<std::array<int, 3>, int> n;  // (type, entity dim, entity tag) -> count
    for (const auto& [tag, e] : g.elements) ++n[{std::get<0>(e), std::get<1>(e), std::get<2>(e)}];
    return n;
  };
  EXPECT_EQ(census(a), census(b));
  std::string log;
  EXPECT_EQ(run(testing::cli_path() + " check " + out_msh, &log), 0) << log;
}

// --fix-boundary, and the paper's methods (which keep the boundary: here every vertex), move no
// vertex.
TEST(SurfaceMesh3, FixedBoundaryMovesNoVertex) {
  const std::string dir = testing::temp_dir();
  const MeshData input = read_mesh(mesh_geo(dir, kOctant, "octant"));
  for (const std::string method : {"", "cvdt", "smooth"}) {
    MeshData d = input;
    OptimizeOptions o;
    o.fix_boundary = method.empty();
    if (!method.empty()) o.method = method;
    const OptimizeResult r = optimize(d, o);
    EXPECT_EQ(d.tet.xyz, input.tet.xyz) << method;
    EXPECT_TRUE(worse_than(r.after, r.before).empty()) << method;
    EXPECT_TRUE(check_mesh(d.tet).ok) << method;
  }
}

TEST(SurfaceMesh3, PlateOutsideZConstIsReadAndStaysInItsPlane) {
  const std::string dir = testing::temp_dir();
  // A graded square in the plane x = 0 (not z = const: not a 2D mesh).
  const std::string msh = mesh_geo(
      dir,
      "Point(1) = {0, 0, 0, 0.03};\nPoint(2) = {0, 1, 0, 0.2};\nPoint(3) = {0, 1, 1, 0.2};\n"
      "Point(4) = {0, 0, 1, 0.1};\nLine(1) = {1, 2};\nLine(2) = {2, 3};\nLine(3) = {3, 4};\n"
      "Line(4) = {4, 1};\nCurve Loop(1) = {1, 2, 3, 4};\nPlane Surface(1) = {1};\n",
      "plate");
  MeshData d = read_mesh(msh);
  ASSERT_EQ(d.dim, 3);
  ASSERT_TRUE(is_surface_mesh(d.tet));
  const OptimizeResult r = optimize(d, OptimizeOptions{});
  EXPECT_TRUE(worse_than(r.after, r.before).empty());
  for (int v = 0; v < d.tet.nb_vertices(); ++v) EXPECT_NEAR(d.tet.point(v)[0], 0, 1e-12);
  EXPECT_TRUE(check_mesh(d.tet).ok);
}

// Gmsh's demos/boolean/surface_filling.geo: four fillings of one curve loop, crossing one another.
// Every edge is on an even number of triangles, so the file looks like a closed shell, but Gmsh
// cannot mesh a volume inside ("overlapping facets"): read as a surface mesh, optimized through
// the CLI, the output accepted by `check`.
TEST(SurfaceMesh3, FillingsOfOneLoopThatBoundNoVolumeGoThroughTheCli) {
  const std::string dir = testing::temp_dir();
  const std::string msh =
      mesh_geo(dir,
               "SetFactory(\"OpenCASCADE\");\nMesh.MeshSizeMin = 0.04;\nMesh.MeshSizeMax = 0.04;\n"
               "Point(1) = {-0.8, 0.1, -0.2, 1.0};\nPoint(2) = {-0.5, 0.1, -0.2, 1.0};\n"
               "Point(3) = {-0.6, 0, -0.1, 1.0};\nPoint(4) = {-0.7, -0, -0.1, 1.0};\n"
               "Point(5) = {-0.7, 0.2, -0.2, 1.0};\nPoint(6) = {-0.6, 0.1, -0.1, 1.0};\n"
               "Spline(1) = {1, 5, 2};\nSpline(2) = {2, 6, 3};\nSpline(3) = {3, 4, 1};\n"
               "Curve Loop(1) = {1, 2, 3};\nSurface(1) = {1};\nBSpline Surface(2) = {1};\n"
               "BSpline Surface(3) = {1};\nPoint(7) = {-0.7, 0.1, -0.2, 1.0};\n"
               "Point(8) = {-0.67, 0.1, -0.2, 1.0};\nSurface(4) = {1} Using Point {7,8};\n",
               "filling");
  const MeshData d = read_mesh(msh);
  ASSERT_EQ(d.dim, 3);
  ASSERT_TRUE(is_surface_mesh(d.tet));
  bool noted = false;
  for (const auto& n : d.model().read_notes)
    noted |= n.find("cannot be meshed") != std::string::npos;
  EXPECT_TRUE(noted);
  const std::string out = dir + "/filling_opt.msh";
  std::string log;
  ASSERT_EQ(run(testing::cli_path() + " optimize " + msh + " -o " + out, &log), 0) << log;
  EXPECT_NE(log.find("minimum angle"), std::string::npos) << log;
  EXPECT_EQ(run(testing::cli_path() + " check " + out, &log), 0) << log;
  EXPECT_NE(log.find("surface mesh in space"), std::string::npos) << log;
  const MeshData o = read_mesh(out);
  ASSERT_TRUE(is_surface_mesh(o.tet));
  EXPECT_EQ(o.tet.nb_tris(), d.tet.nb_tris());
  EXPECT_GE(min_quality(o.tet, Measure::kMinAngle), min_quality(d.tet, Measure::kMinAngle));
  EXPECT_GE(min_quality(o.tet, Measure::kQ), min_quality(d.tet, Measure::kQ));
}

// A sphere octant with a recombined (quadrangle) plane beside it: the quadrangles are kept as they
// are, their nodes do not move, the triangles are optimized.
TEST(SurfaceMesh3, QuadranglesBesideTheTrianglesArePinned) {
  const std::string dir = testing::temp_dir();
  const std::string msh =
      mesh_geo(dir,
               std::string(kOctant) +
                   "Point(5) = {2, 0, 0, 0.1};\nPoint(6) = {2, 1, 0, 0.1};\nLine(4) = {2, 5};\n"
                   "Line(5) = {5, 6};\nLine(6) = {6, 3};\nCurve Loop(2) = {4, 5, 6, -1};\n"
                   "Plane Surface(2) = {2};\nRecombine Surface{2};\nPhysical Surface(\"plate\", "
                   "10) = {2};\n",
               "mixed");
  MeshData d = read_mesh(msh);
  ASSERT_TRUE(is_surface_mesh(d.tet));
  std::set<int> quad_nodes;
  long nb_quads = 0;
  for (const ElementBlock& b : d.tet.model.extra)
    if (b.gmsh_type == 3) {
      quad_nodes.insert(b.nodes.begin(), b.nodes.end());
      nb_quads += static_cast<long>(b.tags.size());
    }
  ASSERT_GT(nb_quads, 0);
  const TetMesh input = d.tet;
  const OptimizeResult r = optimize(d, OptimizeOptions{});
  EXPECT_TRUE(worse_than(r.after, r.before).empty());
  for (int v : quad_nodes)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(d.tet.point(v)[k], input.point(v)[k]) << v;
  long after = 0;
  for (const ElementBlock& b : d.tet.model.extra)
    if (b.gmsh_type == 3) after += static_cast<long>(b.tags.size());
  EXPECT_EQ(after, nb_quads);
  EXPECT_TRUE(check_mesh(d.tet).ok);
}

// An open surface in an .stl (the octant exported by Gmsh): a surface mesh in space, optimized and
// written back as an .stl that reads again as the same surface mesh.
TEST(SurfaceMesh3, OpenStlInSpaceIsOptimizedAndWrittenBack) {
  const std::string dir = testing::temp_dir();
  const std::string geo = dir + "/octant.geo", stl = dir + "/octant.stl";
  std::ofstream(geo) << kOctant;
  std::string log;
  ASSERT_EQ(run("gmsh -v 0 -2 " + geo + " -o " + stl, &log), 0) << log;
  MeshData d = read_mesh(stl);
  ASSERT_EQ(d.dim, 3);
  ASSERT_TRUE(is_surface_mesh(d.tet));
  const OptimizeResult r = optimize(d, OptimizeOptions{});
  EXPECT_TRUE(worse_than(r.after, r.before).empty());
  const std::string out = dir + "/octant_opt.stl";
  write_mesh(d, out);
  const MeshData back = read_mesh(out);
  ASSERT_TRUE(is_surface_mesh(back.tet));
  EXPECT_EQ(back.tet.nb_tris(), d.tet.nb_tris());
  EXPECT_EQ(run(testing::cli_path() + " check " + out, &log), 0) << log;
}

// Two triangles of a long thin rhombus split along its long diagonal.
TetMesh rhombus(int surface2) {
  TetMesh m;
  m.xyz = {0, 0, 0, 4, 0, 0, 2, 0.5, 0, 2, -0.5, 0};
  m.vclass.assign(4, {2, 1});
  m.tris = {0, 1, 2, 1, 0, 3};
  m.tri_surface = {1, surface2};
  return m;
}

BoundaryModel free_model(const TetMesh& m) {
  BoundaryModel b = make_discrete_boundary(m);
  b.curve_edges.clear();  // every edge flippable for the micro test
  return b;
}

TEST(SurfaceMesh3, FlipTakesTheShortDiagonalOfOneSurfaceOnly) {
  {
    TetMesh m = rhombus(1);
    const SurfaceFlipStats s = flip_surface_edges(m, free_model(m));
    EXPECT_EQ(s.nb_flipped, 1);
    std::set<int> e1(m.tris.begin(), m.tris.begin() + 3), e2(m.tris.begin() + 3, m.tris.end());
    EXPECT_TRUE(e1.count(2) && e1.count(3) && e2.count(2) && e2.count(3));
    EXPECT_TRUE(check_mesh(m).ok);
    EXPECT_TRUE(folded_triangle_pairs(m).empty());
  }
  {
    TetMesh m = rhombus(2);  // two surfaces: their common edge is a curve
    EXPECT_EQ(flip_surface_edges(m, free_model(m)).nb_flipped, 0);
  }
  {
    TetMesh m = rhombus(1);  // a line element of the file on the diagonal
    SurfaceFlipOptions o;
    o.kept_edges = {{0, 1}};
    EXPECT_EQ(flip_surface_edges(m, free_model(m), o).nb_flipped, 0);
  }
}

TEST(SurfaceMesh3, CheckFindsFoldsDuplicatesAndFlatTriangles) {
  TetMesh m;
  m.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.2, 0.9, 0.01, 2, 0, 0};
  m.vclass.assign(5, {2, 1});
  m.tris = {0, 1, 2, 1, 0, 3};  // (0,1,3) lies over (0,1,2): folded onto it
  m.tri_surface = {1, 1};
  EXPECT_TRUE(check_surface_mesh(m).ok);
  EXPECT_EQ(folded_triangle_pairs(m).size(), 1u);
  TetMesh dup = m;
  dup.tris = {0, 1, 2, 2, 1, 0};
  EXPECT_FALSE(check_mesh(dup).ok);
  dup.tri_surface = {1, 2};  // one triangle on two surfaces: allowed
  EXPECT_TRUE(check_mesh(dup).ok);
  TetMesh flat = m;
  flat.tris = {0, 1, 4, 0, 1, 2};
  EXPECT_FALSE(check_mesh(flat).ok);
}

}  // namespace
}  // namespace cvtmesh
