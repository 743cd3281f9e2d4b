#include "tests/support/test_meshes.h"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "core/geometry/predicates.h"
#include "core/mesh/build_adjacency.h"

namespace cvtmesh::testing {

std::string geo_path(const std::string& name) {
  return std::string(CVTMESH_SOURCE_DIR) + "/geo/" + name;
}
std::string cli_path() {
  return CVTMESH_CLI_PATH;
}
std::string shared_path(const std::string& rel) {
  return std::string(CVTMESH_SHARED_DIR) + "/" + rel;
}

namespace {
// Temporary directories made by the tests, removed when the test program exits.
std::vector<std::string>& made_dirs() {
  static std::vector<std::string> dirs;
  return dirs;
}
void remove_made_dirs() {
  std::error_code ec;
  for (const auto& d : made_dirs()) std::filesystem::remove_all(d, ec);
}
}  // namespace

std::string temp_dir() {
  char tmpl[] = "/tmp/cvtmesh-test-XXXXXX";
  const char* d = mkdtemp(tmpl);
  if (!d) return std::string("/tmp");
  if (made_dirs().empty()) std::atexit(remove_made_dirs);
  made_dirs().push_back(d);
  return std::string(d);
}

int run(const std::string& cmd, std::string* output) {
  std::string full = cmd + " 2>&1";
  FILE* p = popen(full.c_str(), "r");
  if (!p) return -1;
  std::array<char, 4096> buf;
  std::string out;
  std::size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  const int status = pclose(p);
  if (output) *output = out;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

TetMesh cube6() {
  TetMesh m;
  for (int i = 0; i < 8; ++i) {
    m.xyz.push_back(i & 1);
    m.xyz.push_back((i >> 1) & 1);
    m.xyz.push_back((i >> 2) & 1);
  }
  // Kuhn triangulation: paths from 0 to 7 through the cube's vertices.
  const int paths[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                           {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
  for (const auto& p : paths) {
    int t[4] = {p[0], p[1], p[2], p[3]};
    if (orient3d(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(t[3])) < 0)
      std::swap(t[2], t[3]);
    m.tets.insert(m.tets.end(), t, t + 4);
    m.tet_region.push_back(1);
  }
  build_adjacency(m);
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int f = 0; f < 4; ++f)
      if (m.adj[4 * t + f] < 0) {
        for (int k = 0; k < 3; ++k) m.tris.push_back(m.tets[4 * t + kTetFace[f][k]]);
        m.tri_surface.push_back(1);
      }
  m.vclass.assign(8, VertexClass{2, 1});
  return m;
}

TriMesh2 square2() {
  TriMesh2 m;
  m.xy = {0, 0, 1, 0, 1, 1, 0, 1};
  m.tris = {0, 1, 2, 0, 2, 3};
  m.tri_region = {1, 1};
  m.edges = {0, 1, 1, 2, 2, 3, 3, 0};
  m.edge_curve = {1, 2, 3, 4};
  m.vclass.assign(4, VertexClass{0, 1});
  build_adjacency2(m);
  return m;
}

}  // namespace cvtmesh::testing

#include <tetgen.h>

#include "core/delaunay/tetgen_library.h"

namespace cvtmesh::testing {

TetMesh delaunay_of_points(const std::vector<double>& xyz) {
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(xyz.size() / 3);
  in.pointlist = new REAL[xyz.size()];
  std::copy(xyz.begin(), xyz.end(), in.pointlist);
  char sw[] = "zQ";
  tetgen_library().tetrahedralize(sw, &in, &out, nullptr, nullptr);
  TetMesh m;
  m.xyz = xyz;
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    int v[4];
    for (int k = 0; k < 4; ++k) v[k] = out.tetrahedronlist[4 * t + k];
    if (orient3d(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])) < 0)
      std::swap(v[2], v[3]);
    m.tets.insert(m.tets.end(), v, v + 4);
    m.tet_region.push_back(1);
  }
  build_adjacency(m);
  m.vclass.assign(m.nb_vertices(), VertexClass{3, 1});
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int f = 0; f < 4; ++f)
      if (m.adj[4 * t + f] < 0) {
        for (int k = 0; k < 3; ++k) {
          const int v = m.tets[4 * t + kTetFace[f][k]];
          m.tris.push_back(v);
          m.vclass[v] = VertexClass{2, 1};
        }
        m.tri_surface.push_back(1);
      }
  return m;
}

std::vector<double> bcc_lattice(int n, double a) {
  std::vector<double> p;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) p.insert(p.end(), {i * a, j * a, k * a});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) p.insert(p.end(), {(i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a});
  return p;
}

}  // namespace cvtmesh::testing
