#include "tests/support/test_meshes.h"

#include <array>
#include <cstdio>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <filesystem>
#include <unistd.h>

#include "core/geometry/predicates.h"
#include "core/io/read_mesh.h"
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

std::string unprivileged_prefix() {
  static const std::string prefix = [] {
    if (geteuid() != 0) return std::string();
    const std::string p = "setpriv --reuid=65534 --regid=65534 --clear-groups ";
    std::string out;
    return run(p + cli_path() + " --version", &out) == 0 ? p : std::string();
  }();
  return prefix;
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

TetMesh make_tet_mesh(const std::vector<std::array<double, 3>>& points,
                      const std::vector<std::array<int, 4>>& tets,
                      const std::vector<int>& interior) {
  TetMesh m;
  for (const auto& p : points) m.xyz.insert(m.xyz.end(), p.begin(), p.end());
  for (auto t : tets) {
    if (orient3d(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(t[3])) < 0)
      std::swap(t[2], t[3]);
    m.tets.insert(m.tets.end(), t.begin(), t.end());
    m.tet_region.push_back(1);
  }
  build_adjacency(m);
  for (int t = 0; t < m.nb_tets(); ++t)
    for (int f = 0; f < 4; ++f)
      if (m.adj[4 * t + f] < 0) {
        for (int k = 0; k < 3; ++k) m.tris.push_back(m.tets[4 * t + kTetFace[f][k]]);
        m.tri_surface.push_back(1);
      }
  m.vclass.assign(points.size(), VertexClass{2, 1});
  for (int v : interior) m.vclass[v] = VertexClass{3, 1};
  return m;
}

MeshData cube_sphere(double h, double h_ball, bool gmsh_optimize,
                     const std::vector<std::pair<std::string, double>>& extra) {
  ReadOptions ro;
  ro.gmsh_optimize = gmsh_optimize;
  ro.set_numbers = {{"h", h}, {"h_ball", h_ball}};
  ro.set_numbers.insert(ro.set_numbers.end(), extra.begin(), extra.end());
  return read_mesh(geo_path("cube_sphere.geo"), ro);
}

double max_nearest_distance(const TriMesh2& a, const TriMesh2& b) {
  double worst = 0;
  for (int i = 0; i < a.nb_vertices(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < b.nb_vertices(); ++j)
      best =
          std::min(best, std::hypot(a.point(i)[0] - b.point(j)[0], a.point(i)[1] - b.point(j)[1]));
    worst = std::max(worst, best);
  }
  return worst;
}

TetMesh cube6() {
  std::vector<std::array<double, 3>> pts;
  for (int i = 0; i < 8; ++i)
    pts.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  // Kuhn triangulation: paths from 0 to 7 through the cube's vertices.
  return make_tet_mesh(
      pts, {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}});
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

#include "core/geometry/tetgen_library.h"

namespace cvtmesh::testing {

TetMesh delaunay_of_points(const std::vector<double>& xyz) {
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(xyz.size() / 3);
  in.pointlist = new REAL[xyz.size()];
  std::copy(xyz.begin(), xyz.end(), in.pointlist);
  char sw[] = "zQ";
  tetgen_library().tetrahedralize(sw, &in, &out, nullptr, nullptr);
  std::vector<std::array<double, 3>> pts(xyz.size() / 3);
  for (std::size_t i = 0; i < pts.size(); ++i)
    pts[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  std::vector<std::array<int, 4>> tets(out.numberoftetrahedra);
  for (int t = 0; t < out.numberoftetrahedra; ++t)
    for (int k = 0; k < 4; ++k) tets[t][k] = out.tetrahedronlist[4 * t + k];
  // Hull vertices are fixed, the others interior.
  TetMesh m = make_tet_mesh(pts, tets);
  std::vector<char> on_hull(pts.size(), 0);
  for (int v : m.tris) on_hull[v] = 1;
  for (std::size_t v = 0; v < pts.size(); ++v)
    if (!on_hull[v]) m.vclass[v] = VertexClass{3, 1};
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

std::vector<double> cube_lattice(int n, double jitter) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<double> p;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        const bool interior = i > 0 && i < n && j > 0 && j < n && k > 0 && k < n;
        for (int c : {i, j, k}) p.push_back(c + (interior && jitter > 0 ? jitter * u(rng) : 0.0));
      }
  return p;
}

std::vector<double> cube_lattice_with_hull_points() {
  std::vector<double> p = cube_lattice(3);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j <= 3; ++j) {
      p.insert(p.end(), {i + 0.5, double(j), 0.0});
      p.insert(p.end(), {double(j), i + 0.5, 0.0});
    }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) p.insert(p.end(), {i + 0.5, j + 0.5, 3.0});
  return p;
}

TetMesh jittered_box(int n, double amount, unsigned seed) {
  std::vector<double> xyz;
  unsigned state = seed;
  auto rnd = [&] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / double(1 << 24) * 2 - 1;
  };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int k = 0; k <= n; ++k) {
        double p[3] = {double(i), double(j), double(k)};
        for (int d = 0; d < 3; ++d) {
          const double r = rnd();
          if (p[d] != 0 && p[d] != n) p[d] += amount * r;
        }
        xyz.insert(xyz.end(), p, p + 3);
      }
  return delaunay_of_points(xyz);
}

}  // namespace cvtmesh::testing
