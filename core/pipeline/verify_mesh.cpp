#include "core/pipeline/verify_mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "core/geometry/tet_geometry.h"
#include "core/mesh/check_mesh.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

template <class Mesh>
void check_valid(const Mesh& m) {
  const MeshCheck c = check_mesh(m);
  if (!c.ok) throw InvariantError("optimized mesh is invalid: " + c.problems.front());
}

std::string str(double v) {
  return std::to_string(v);
}

}  // namespace

std::vector<std::pair<int, double>> region_volumes(const TetMesh& m) {
  std::map<int, double> vol;
  for (int t = 0; t < m.nb_tets(); ++t) {
    const int* v = &m.tets[4 * t];
    if (v[0] < 0) continue;
    vol[m.tet_region[t]] += tet_volume(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
  }
  return {vol.begin(), vol.end()};
}

void verify_optimized(const TetMesh& before, const TetMesh& after) {
  check_valid(after);
  // Fixed vertices (on surfaces, curves, corners) keep their ids and coordinates.
  if (after.nb_vertices() < before.nb_vertices())
    throw InvariantError("optimized mesh lost vertices (" + std::to_string(before.nb_vertices()) +
                         " -> " + std::to_string(after.nb_vertices()) + ")");
  for (int v = 0; v < before.nb_vertices(); ++v)
    if (before.vclass[v].dim < 3)
      for (int d = 0; d < 3; ++d)
        if (before.point(v)[d] != after.point(v)[d])
          throw InvariantError("boundary vertex " + std::to_string(v) + " moved");
  // Same constrained triangles with the same surface tags.
  auto tri_set = [](const TetMesh& m) {
    std::multiset<std::tuple<int, int, int, int>> s;
    for (int f = 0; f < m.nb_tris(); ++f) {
      int a = m.tris[3 * f], b = m.tris[3 * f + 1], c = m.tris[3 * f + 2];
      int k[3] = {a, b, c};
      std::sort(k, k + 3);
      s.insert({k[0], k[1], k[2], m.tri_surface[f]});
    }
    return s;
  };
  if (tri_set(before) != tri_set(after))
    throw InvariantError("boundary or interface triangles changed");
  // Region volumes conserved.
  const auto vb = region_volumes(before), va = region_volumes(after);
  if (vb.size() != va.size()) throw InvariantError("a region disappeared or appeared");
  for (std::size_t i = 0; i < vb.size(); ++i) {
    if (vb[i].first != va[i].first) throw InvariantError("region tags changed");
    // The volume of a region bounded by fixed triangles is fixed; the sums differ by rounding only.
    const double tol = 1e-10 * std::fabs(vb[i].second);
    if (std::fabs(vb[i].second - va[i].second) > tol)
      throw InvariantError("volume of region " + std::to_string(vb[i].first) + " changed from " +
                           str(vb[i].second) + " to " + str(va[i].second));
  }
  if (before.model.groups.size() != after.model.groups.size())
    throw InvariantError("physical groups changed");
}

void verify_optimized(const TriMesh2& before, const TriMesh2& after) {
  check_valid(after);
  if (after.nb_vertices() < before.nb_vertices())
    throw InvariantError("optimized mesh lost vertices");
  for (int v = 0; v < before.nb_vertices(); ++v)
    if (before.vclass[v].dim < 2)
      for (int d = 0; d < 2; ++d)
        if (before.point(v)[d] != after.point(v)[d])
          throw InvariantError("boundary vertex " + std::to_string(v) + " moved");
  auto edge_set = [](const TriMesh2& m) {
    std::multiset<std::tuple<int, int, int>> s;
    for (int e = 0; e < m.nb_edges(); ++e)
      s.insert({std::min(m.edges[2 * e], m.edges[2 * e + 1]),
                std::max(m.edges[2 * e], m.edges[2 * e + 1]), m.edge_curve[e]});
    return s;
  };
  if (edge_set(before) != edge_set(after))
    throw InvariantError("boundary or interface edges changed");
  std::map<int, double> ab, aa;
  for (int t = 0; t < before.nb_tris(); ++t)
    if (before.tris[3 * t] >= 0)
      ab[before.tri_region[t]] +=
          tri_area2d(before.point(before.tris[3 * t]), before.point(before.tris[3 * t + 1]),
                     before.point(before.tris[3 * t + 2]));
  for (int t = 0; t < after.nb_tris(); ++t)
    if (after.tris[3 * t] >= 0)
      aa[after.tri_region[t]] +=
          tri_area2d(after.point(after.tris[3 * t]), after.point(after.tris[3 * t + 1]),
                     after.point(after.tris[3 * t + 2]));
  if (ab.size() != aa.size()) throw InvariantError("a surface disappeared or appeared");
  for (const auto& [r, a] : ab)
    if (std::fabs(aa[r] - a) > 1e-10 * std::fabs(a))
      throw InvariantError("area of surface " + std::to_string(r) + " changed");
}

}  // namespace cvtmesh
