// Our own formats: write, read back, compare (VTK legacy/XML, TetGen, Medit, OpenMesh surfaces).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/quality/quality_fields.h"
#include "core/geometry/tet_geometry.h"
#include "core/io/medit_io.h"
#include "core/io/read_mesh.h"
#include "core/io/surface_io.h"
#include "core/io/tetgen_io.h"
#include "core/io/vtk_io.h"
#include "core/io/write_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/optimize.h"
#include "core/util/error.h"
#include "tests/io/gmsh_dump.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

namespace fs = std::filesystem;
using testing::gmsh_dump;

// The two-region cube/ball model, coarse (interfaces, several surfaces, feature curves).
const MeshData& two_regions() {
  static const MeshData d = [] {
    ReadOptions o;
    o.set_numbers = {{"two_regions", 1}, {"h", 0.2}, {"h_ball", 0.12}};
    return read_mesh(testing::geo_path("cube_sphere.geo"), o);
  }();
  return d;
}

// The cube minus the ball, coarse: its boundary has two shells.
const MeshData& cube_minus_ball() {
  static const MeshData d = [] {
    ReadOptions o;
    o.set_numbers = {{"h", 0.2}, {"h_ball", 0.12}};
    return read_mesh(testing::geo_path("cube_sphere.geo"), o);
  }();
  return d;
}

std::string write_geo(const std::string& dir, const std::string& name, const std::string& text) {
  const std::string p = dir + "/" + name;
  std::ofstream(p) << text;
  return p;
}

// A plate with a hole, two regions (the hole filled as a second surface).
const MeshData& plate() {
  static const MeshData d = read_mesh(write_geo(
      testing::temp_dir(), "plate.geo",
      "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 2, 1};\n"
      "Disk(2) = {0.6, 0.5, 0, 0.25};\n"
      "BooleanFragments{Surface{1}; Delete;}{Surface{2}; Delete;}\nMesh.MeshSizeMax = 0.1;\n"));
  return d;
}

using Face = std::array<int, 3>;
std::set<Face> face_set(const std::vector<int>& tris) {
  std::set<Face> s;
  for (std::size_t f = 0; f + 2 < tris.size(); f += 3) {
    Face k{tris[f], tris[f + 1], tris[f + 2]};
    std::sort(k.begin(), k.end());
    s.insert(k);
  }
  return s;
}
std::set<std::array<int, 2>> edge_set(const std::vector<int>& edges) {
  std::set<std::array<int, 2>> s;
  for (std::size_t e = 0; e + 1 < edges.size(); e += 2)
    s.insert({std::min(edges[e], edges[e + 1]), std::max(edges[e], edges[e + 1])});
  return s;
}

void expect_valid(const MeshData& d) {
  const MeshCheck c = d.dim == 3 ? check_mesh(d.tet) : check_mesh(d.tri);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems[0]);
}

// Same vertices (exactly), same elements in the same order, same region tags.
void expect_same_cells(const MeshData& a, const MeshData& b) {
  ASSERT_EQ(a.dim, b.dim);
  if (a.dim == 3) {
    EXPECT_EQ(a.tet.xyz, b.tet.xyz);
    EXPECT_EQ(a.tet.tets, b.tet.tets);
    EXPECT_EQ(a.tet.tet_region, b.tet.tet_region);
  } else {
    EXPECT_EQ(a.tri.xy, b.tri.xy);
    EXPECT_EQ(a.tri.z0, b.tri.z0);
    EXPECT_EQ(a.tri.tris, b.tri.tris);
    EXPECT_EQ(a.tri.tri_region, b.tri.tri_region);
  }
}

void expect_same_facets_and_tags(const MeshData& a, const MeshData& b) {
  if (a.dim == 3) {
    EXPECT_EQ(a.tet.tris, b.tet.tris);
    EXPECT_EQ(a.tet.tri_surface, b.tet.tri_surface);
  } else {
    EXPECT_EQ(a.tri.edges, b.tri.edges);
    EXPECT_EQ(a.tri.edge_curve, b.tri.edge_curve);
  }
}

// ---------------------------------------------------------------------------------------------

TEST(ReadMesh, GeoParametersAreSetBeforeParsing) {
  // --set two_regions=1 (a DefineConstant with a ONELAB name) selects the two-region variant.
  std::set<int> two(two_regions().tet.tet_region.begin(), two_regions().tet.tet_region.end());
  std::set<int> one(cube_minus_ball().tet.tet_region.begin(),
                    cube_minus_ball().tet.tet_region.end());
  EXPECT_EQ(two.size(), 2u);
  EXPECT_EQ(one.size(), 1u);
}

TEST(VtkIo, LegacyAndXmlRoundTripWithCellData) {
  for (const MeshData* d : {&two_regions(), &plate()}) {
    const std::vector<ElementField> fields = quality_fields(*d);
    const std::string dir = testing::temp_dir();
    for (const char* ext : {".vtk", ".vtu"}) {
      const std::string path = dir + "/m" + ext;
      WriteOptions o;
      o.fields = fields;
      write_mesh(*d, path, o);
      std::vector<ElementField> back_fields;
      const MeshData back =
          std::string(ext) == ".vtk" ? read_vtk(path, &back_fields) : read_vtu(path, &back_fields);
      expect_valid(back);
      expect_same_cells(*d, back);
      // VTK holds the elements only: the boundary comes back from the complex, same facets.
      if (d->dim == 3)
        EXPECT_EQ(face_set(back.tet.tris), face_set(d->tet.tris)) << ext;
      else
        EXPECT_EQ(edge_set(back.tri.edges), edge_set(d->tri.edges)) << ext;
      ASSERT_EQ(back_fields.size(), fields.size()) << ext;
      for (std::size_t k = 0; k < fields.size(); ++k) {
        EXPECT_EQ(back_fields[k].values, fields[k].values) << ext << " " << fields[k].name;
        if (std::string(ext) == ".vtu") EXPECT_EQ(back_fields[k].name, fields[k].name);
      }
    }
  }
}

TEST(VtkIo, GmshReadsOurLegacyFile) {
  const std::string path = testing::temp_dir() + "/m.vtk";
  write_mesh(two_regions(), path);
  const testing::GmshDump g = gmsh_dump(path);
  long tets = 0;
  for (const auto& [tag, e] : g.elements) tets += std::get<0>(e) == 4;
  EXPECT_EQ(tets, two_regions().tet.nb_tets());
  EXPECT_EQ(g.nodes.size(), static_cast<std::size_t>(two_regions().tet.nb_vertices()));
}

TEST(TetgenIo, RoundTripKeepsEverythingTheFormatHolds) {
  for (const MeshData* d : {&two_regions(), &plate()}) {
    const std::string dir = testing::temp_dir();
    // Per-element data is refused (meshio reads .ele attributes as integers), before anything
    // is written.
    WriteOptions with_fields;
    with_fields.fields = quality_fields(*d);
    EXPECT_THROW(write_mesh(*d, dir + "/m.node", with_fields), OutputError);
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
    WriteOptions o;
    write_mesh(*d, dir + "/m.node", o);
    const std::string facets = dir + (d->dim == 3 ? "/m.face" : "/m.edge");
    ASSERT_TRUE(fs::exists(dir + "/m.node") && fs::exists(dir + "/m.ele") && fs::exists(facets));
    // No temporaries left behind.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 3);
    for (const char* start : {"/m.node", "/m.ele"}) {
      const MeshData back = read_tetgen(dir + start);
      expect_valid(back);
      expect_same_cells(*d, back);
      expect_same_facets_and_tags(*d, back);
    }
    // .ele: the region, its only attribute.
    std::ifstream ele(dir + "/m.ele");
    std::string line;
    while (std::getline(ele, line) && line[0] == '#') {
    }
    std::istringstream hdr(line);
    long n = 0, npe = 0, nattr = 0;
    hdr >> n >> npe >> nattr;
    EXPECT_EQ(npe, d->dim + 1);
    EXPECT_EQ(nattr, 1);
  }
}

TEST(TetgenIo, WithoutFaceFileTheBoundaryGetsMarkerOne) {
  const MeshData& d = two_regions();
  const std::string dir = testing::temp_dir();
  write_mesh(d, dir + "/m.node");
  fs::remove(dir + "/m.face");
  const MeshData back = read_tetgen(dir + "/m.node");
  expect_valid(back);
  expect_same_cells(d, back);
  EXPECT_EQ(face_set(back.tet.tris), face_set(d.tet.tris));
  // Boundary faces (one tet) have marker 1; the interface between the regions another one.
  std::set<int> boundary_tags, interface_tags;
  const std::set<Face> boundary = [&] {
    std::set<Face> s;
    for (int t = 0; t < back.tet.nb_tets(); ++t)
      for (int f = 0; f < 4; ++f)
        if (back.tet.adj[4 * t + f] < 0) {
          Face k;
          for (int j = 0; j < 3; ++j) k[j] = back.tet.tets[4 * t + kTetFace[f][j]];
          std::sort(k.begin(), k.end());
          s.insert(k);
        }
    return s;
  }();
  for (int f = 0; f < back.tet.nb_tris(); ++f) {
    Face k{back.tet.tris[3 * f], back.tet.tris[3 * f + 1], back.tet.tris[3 * f + 2]};
    std::sort(k.begin(), k.end());
    (boundary.count(k) ? boundary_tags : interface_tags).insert(back.tet.tri_surface[f]);
  }
  EXPECT_EQ(boundary_tags, std::set<int>{1});
  ASSERT_EQ(interface_tags.size(), 1u);
  EXPECT_NE(*interface_tags.begin(), 1);
}

TEST(TetgenIo, ClassificationFromSurfacesMatchesGmshOnABox) {
  // On a box, the vertex classification rebuilt from the surface markers (corner where three
  // faces meet, curve where two meet) is Gmsh's own.
  const std::string dir = testing::temp_dir();
  const MeshData d = read_mesh(write_geo(dir, "box.geo",
                                         "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 2, "
                                         "1.5};\nMesh.MeshSizeMax = 0.35;\n"));
  write_mesh(d, dir + "/box.node");
  const MeshData back = read_tetgen(dir + "/box.node");
  ASSERT_EQ(back.tet.nb_vertices(), d.tet.nb_vertices());
  int corners = 0;
  for (int v = 0; v < d.tet.nb_vertices(); ++v) {
    EXPECT_EQ(back.tet.vclass[v].dim, d.tet.vclass[v].dim) << "vertex " << v;
    corners += back.tet.vclass[v].dim == 0;
  }
  EXPECT_EQ(corners, 8);
  int curves = 0;
  for (const auto& e : back.tet.model.entities) curves += e.dim == 1;
  EXPECT_EQ(curves, 12);
  // The rebuilt model is written as a Gmsh model and read back consistently.
  const std::string msh = dir + "/box.msh";
  write_mesh(back, msh);
  const MeshData again = read_mesh(msh);
  for (int v = 0; v < back.tet.nb_vertices(); ++v)
    EXPECT_EQ(again.tet.vclass[v].dim, back.tet.vclass[v].dim);
}

TEST(MeditIo, RoundTripKeepsCoordinatesConnectivityAndRefs) {
  for (const MeshData* d : {&two_regions(), &plate()}) {
    const std::string path = testing::temp_dir() + "/m.mesh";
    write_mesh(*d, path);
    const MeshData back = read_medit(path);
    expect_valid(back);
    expect_same_cells(*d, back);
    expect_same_facets_and_tags(*d, back);
  }
}

TEST(MeditIo, GmshReadsOurFile) {
  const std::string path = testing::temp_dir() + "/m.mesh";
  write_mesh(two_regions(), path);
  const testing::GmshDump g = gmsh_dump(path);
  long tets = 0, tris = 0;
  std::set<int> regions;
  for (const auto& [tag, e] : g.elements) {
    tets += std::get<0>(e) == 4;
    tris += std::get<0>(e) == 2;
    if (std::get<0>(e) == 4) regions.insert(std::get<2>(e));
  }
  EXPECT_EQ(tets, two_regions().tet.nb_tets());
  EXPECT_EQ(tris, two_regions().tet.nb_tris());
  EXPECT_EQ(regions.size(), 2u);
}

// ---------------------------------------------------------------------------------------------

// Volume enclosed by a closed, outward-oriented surface (divergence theorem).
double enclosed_volume(const SurfaceMesh& s) {
  double v = 0;
  for (std::size_t f = 0; f < s.tris.size(); f += 3) {
    const double* a = &s.xyz[3 * s.tris[f]];
    const double* b = &s.xyz[3 * s.tris[f + 1]];
    const double* c = &s.xyz[3 * s.tris[f + 2]];
    v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
          a[2] * (b[0] * c[1] - b[1] * c[0])) /
         6;
  }
  return v;
}

double mesh_volume(const TetMesh& m) {
  double v = 0;
  for (int t = 0; t < m.nb_tets(); ++t)
    v += tet_volume(m.point(m.tets[4 * t]), m.point(m.tets[4 * t + 1]), m.point(m.tets[4 * t + 2]),
                    m.point(m.tets[4 * t + 3]));
  return v;
}

TEST(SurfaceIo, BoundaryIsWrittenClosedAndOutwardInEveryFormat) {
  const MeshData& d = cube_minus_ball();
  const SurfaceMesh boundary = boundary_surface(d);
  const double vol = mesh_volume(d.tet);
  EXPECT_NEAR(enclosed_volume(boundary), vol, 1e-12);
  const std::string dir = testing::temp_dir();
  for (const char* ext : {".off", ".obj", ".ply", ".stl"}) {
    const std::string path = dir + "/s" + ext;
    write_mesh(d, path);
    const SurfaceMesh s = read_surface(path, true);
    EXPECT_EQ(s.tris.size(), boundary.tris.size()) << ext;
    EXPECT_EQ(s.xyz.size(), boundary.xyz.size()) << ext;
    // OpenMesh 9 keeps surface coordinates in single precision (every format).
    const double tol = 1e-6;
    EXPECT_NEAR(enclosed_volume(s), vol, tol) << ext << ": not closed or not outward";
  }
  // Gmsh reads our STL too.
  const testing::GmshDump g = gmsh_dump(dir + "/s.stl");
  EXPECT_EQ(g.elements.size(), boundary.tris.size() / 3);
}

TEST(SurfaceIo, ClosedSurfaceIsTetrahedralizedWithItsCavity) {
  const MeshData& d = cube_minus_ball();
  const std::string path = testing::temp_dir() + "/s.off";
  write_mesh(d, path);
  const SurfaceMesh s = read_surface(path, true);
  const MeshData v = read_mesh(path);
  ASSERT_EQ(v.dim, 3);
  expect_valid(v);
  // The ball stays empty: same volume as the surface encloses, and the tets' boundary is the
  // surface, triangle for triangle.
  EXPECT_NEAR(mesh_volume(v.tet), enclosed_volume(s), 1e-12);
  const SurfaceMesh b = boundary_surface(v);
  EXPECT_EQ(b.tris.size(), s.tris.size());
  std::set<std::array<double, 9>> ts, tb;
  auto tri_coords = [](const SurfaceMesh& m, std::set<std::array<double, 9>>& out) {
    for (std::size_t f = 0; f < m.tris.size(); f += 3) {
      std::array<std::array<double, 3>, 3> p;
      for (int k = 0; k < 3; ++k)
        for (int j = 0; j < 3; ++j) p[k][j] = m.xyz[3 * m.tris[f + k] + j];
      std::sort(p.begin(), p.end());
      std::array<double, 9> flat;
      for (int k = 0; k < 9; ++k) flat[k] = p[k / 3][k % 3];
      out.insert(flat);
    }
  };
  tri_coords(s, ts);
  tri_coords(b, tb);
  EXPECT_TRUE(ts == tb) << "the volume mesh does not keep the surface triangles";
}

TEST(SurfaceIo, PlanarSurfaceReadsAs2D) {
  const std::string path = testing::temp_dir() + "/p.obj";
  write_mesh(plate(), path);
  ReadOptions o;
  o.dim = 2;
  const MeshData back = read_mesh(path, o);
  ASSERT_EQ(back.dim, 2);
  expect_valid(back);
  EXPECT_EQ(back.tri.nb_tris(), plate().tri.nb_tris());
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

// A tetrahedron's surface 1e5 from the origin, with coordinates single precision cannot hold
// (float spacing there is 0.0078): each surface format that can store doubles must give them back
// exactly (ASCII .off/.obj/.stl, ASCII and binary little-endian .ply).
TEST(SurfaceIo, CoordinatesAreReadInDoublePrecisionInEveryTextFormatAndBinaryPly) {
  const double o = 1e5;
  const std::vector<std::array<double, 3>> p = {{o + 0.0011, o + 0.0023, o + 0.0031},
                                                {o + 1.0013, o + 0.0027, o + 0.0039},
                                                {o + 0.0017, o + 1.0029, o + 0.0041},
                                                {o + 0.0019, o + 0.0037, o + 1.0043}};
  const std::vector<std::array<int, 3>> f = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const std::string dir = testing::temp_dir();
  auto num = [](double x) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", x);
    return std::string(b);
  };
  std::map<std::string, std::string> files;
  {
    std::ostringstream s;
    s << "solid t\n";
    for (const auto& t : f) {
      s << "facet normal 0 0 0\nouter loop\n";
      for (int k : t)
        s << "vertex " << num(p[k][0]) << " " << num(p[k][1]) << " " << num(p[k][2]) << "\n";
      s << "endloop\nendfacet\n";
    }
    s << "endsolid t\n";
    files["t.stl"] = s.str();
  }
  for (const bool binary : {false, true}) {
    std::ostringstream s;
    s << "ply\nformat " << (binary ? "binary_little_endian" : "ascii")
      << " 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
         "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto& q : p) {
      if (binary)
        s.write(reinterpret_cast<const char*>(q.data()), 3 * sizeof(double));
      else
        s << num(q[0]) << " " << num(q[1]) << " " << num(q[2]) << "\n";
    }
    for (const auto& t : f) {
      if (binary) {
        const unsigned char n = 3;
        s.write(reinterpret_cast<const char*>(&n), 1);
        s.write(reinterpret_cast<const char*>(t.data()), 3 * sizeof(int));
      } else {
        s << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
      }
    }
    files[binary ? "tb.ply" : "t.ply"] = s.str();
  }
  {
    std::ostringstream s;
    s << "OFF\n4 4 0\n";
    for (const auto& q : p) s << num(q[0]) << " " << num(q[1]) << " " << num(q[2]) << "\n";
    for (const auto& t : f) s << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    files["t.off"] = s.str();
  }
  for (const auto& [name, text] : files) {
    const std::string path = dir + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    const SurfaceMesh s = read_surface(path, true);
    ASSERT_EQ(s.xyz.size(), 12u) << name;
    for (int v = 0; v < 4; ++v) {
      bool found = false;
      for (const auto& q : p)
        found |= s.xyz[3 * v] == q[0] && s.xyz[3 * v + 1] == q[1] && s.xyz[3 * v + 2] == q[2];
      EXPECT_TRUE(found) << name << " vertex " << v << ": " << num(s.xyz[3 * v]);
    }
  }
}

}  // namespace
}  // namespace cvtmesh

namespace cvtmesh {
namespace {

// A Medit .mesh's 3D Edges (MMG's ridges) are kept: read as line blocks, written back by the
// Medit writer with their references, through optimize too, and as lines in a .msh.
TEST(MeditIo, EdgesOfATetMeshAreKeptWithTheirRefs) {
  const TetMesh c = testing::cube6();
  std::set<std::array<int, 3>> edges;  // (a, b, ref) with a < b, 1-based
  for (int a = 0; a < 8; ++a)
    for (int axis = 0; axis < 3; ++axis)
      if (!(a >> axis & 1)) edges.insert({a + 1, (a | 1 << axis) + 1, 10 + axis});
  ASSERT_EQ(edges.size(), 12u);
  std::ostringstream s;
  s << "MeshVersionFormatted 2\nDimension 3\nVertices\n8\n";
  for (int v = 0; v < 8; ++v)
    s << c.point(v)[0] << " " << c.point(v)[1] << " " << c.point(v)[2] << " 0\n";
  s << "Edges\n12\n";
  for (const auto& e : edges) s << e[0] << " " << e[1] << " " << e[2] << "\n";
  s << "Triangles\n" << c.nb_tris() << "\n";
  for (int t = 0; t < c.nb_tris(); ++t)
    s << c.tris[3 * t] + 1 << " " << c.tris[3 * t + 1] + 1 << " " << c.tris[3 * t + 2] + 1
      << " 1\n";
  s << "Tetrahedra\n6\n";
  for (int t = 0; t < 6; ++t)
    s << c.tets[4 * t] + 1 << " " << c.tets[4 * t + 1] + 1 << " " << c.tets[4 * t + 2] + 1 << " "
      << c.tets[4 * t + 3] + 1 << " 1\n";
  s << "End\n";
  const std::string dir = testing::temp_dir();
  std::ofstream(dir + "/edges.mesh") << s.str();
  // The edges of a mesh as (a, b, ref), 1-based, a < b, by coordinates back to the input's ids.
  auto edges_of = [&](const MeshData& d) {
    std::set<std::array<int, 3>> out;
    auto id = [&](int v) {
      const double* p = d.tet.point(v);
      return static_cast<int>(p[0] + 2 * p[1] + 4 * p[2]) + 1;
    };
    for (const ElementBlock& b : d.tet.model.extra)
      for (std::size_t e = 0; e < b.medit_refs.size(); ++e) {
        const int a = id(b.nodes[2 * e]), bb = id(b.nodes[2 * e + 1]);
        out.insert({std::min(a, bb), std::max(a, bb), b.medit_refs[e]});
      }
    return out;
  };
  MeshData d = read_mesh(dir + "/edges.mesh");
  EXPECT_EQ(edges_of(d), edges);
  OptimizeOptions o;
  o.max_iterations = 3;
  optimize(d, o);
  write_mesh(d, dir + "/edges_out.mesh");
  const MeshData back = read_mesh(dir + "/edges_out.mesh");
  expect_valid(back);
  EXPECT_EQ(edges_of(back), edges);
  // As lines in a .msh.
  write_mesh(d, dir + "/edges_out.msh");
  const testing::GmshDump g = gmsh_dump(dir + "/edges_out.msh");
  long lines = 0;
  for (const auto& [tag, e] : g.elements) lines += std::get<0>(e) == 1;
  EXPECT_GE(lines, 12);
}

}  // namespace
}  // namespace cvtmesh
