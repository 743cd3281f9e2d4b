#include "bench/baselines/cgal_remesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/Tetrahedral_remeshing/Remeshing_triangulation_3.h>
#include <CGAL/tetrahedral_remeshing.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>
#include <vector>

#include "bench/baselines/verify_peer.h"
#include "core/util/error.h"

namespace cvtmesh {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Tr = CGAL::Tetrahedral_remeshing::Remeshing_triangulation_3<K>;

double mean_edge_length(const TetMesh& m) {
  double sum = 0;
  long n = 0;
  for (int t = 0; t < m.nb_tets(); ++t) {
    if (m.tets[4 * t] < 0) continue;
    for (const auto& e : kTetEdge) {
      const double* a = m.point(m.tets[4 * t + e[0]]);
      const double* b = m.point(m.tets[4 * t + e[1]]);
      sum += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                       (a[2] - b[2]) * (a[2] - b[2]));
      ++n;
    }
  }
  return n ? sum / static_cast<double>(n) : 0;
}

}  // namespace

void cgal_remesh(TetMesh& m, const CgalRemeshOptions& o) {
  // The vertices of tets only, renumbered: a point of no cell (a node of the model's curves or
  // points, or of a surface bounding no volume: Gmsh's t2, t3, t5, t19) has no incident cell in
  // CGAL's triangulation, and the remeshing then crashes walking around it. The result is matched
  // back by coordinates (classify_peer_vertices).
  std::vector<int> local(static_cast<std::size_t>(m.nb_vertices()), -1);
  std::vector<Tr::Point> points;
  std::vector<std::array<int, 5>> cells;
  auto local_id = [&](int v) {
    if (local[v] < 0) {
      local[v] = static_cast<int>(points.size());
      points.emplace_back(m.xyz[3 * v], m.xyz[3 * v + 1], m.xyz[3 * v + 2]);
    }
    return local[v];
  };
  for (int t = 0; t < m.nb_tets(); ++t) {
    if (m.tets[4 * t] < 0) continue;
    if (m.tet_region[t] <= 0)
      throw InvariantError("CGAL baseline: region tag " + std::to_string(m.tet_region[t]) +
                           " (CGAL's subdomain 0 is the outside)");
    cells.push_back({local_id(m.tets[4 * t]), local_id(m.tets[4 * t + 1]),
                     local_id(m.tets[4 * t + 2]), local_id(m.tets[4 * t + 3]), m.tet_region[t]});
  }
  std::map<std::array<int, 3>, Tr::Cell::Surface_patch_index> border;
  for (int f = 0; f < m.nb_tris(); ++f) {
    std::array<int, 3> k = {local[m.tris[3 * f]], local[m.tris[3 * f + 1]],
                            local[m.tris[3 * f + 2]]};
    if (*std::min_element(k.begin(), k.end()) < 0) continue;  // not on a tet
    std::rotate(k.begin(), std::min_element(k.begin(), k.end()), k.end());
    border[k] = m.tri_surface[f];
  }
  Tr tr;
  std::vector<Tr::Vertex_handle> handles;
  if (!CGAL::build_triangulation<Tr, true>(tr, points, cells, border, handles))
    throw InvariantError("CGAL baseline: the mesh could not be loaded as a triangulation");
  const double target = o.target_edge_length > 0 ? o.target_edge_length : mean_edge_length(m);
  CGAL::tetrahedral_isotropic_remeshing(
      tr, target, CGAL::parameters::remesh_boundaries(false).number_of_iterations(o.iterations));

  TetMesh after;
  std::unordered_map<Tr::Vertex_handle, int> id;
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    id[v] = after.nb_vertices();
    const auto& p = tr.point(v);
    after.xyz.insert(after.xyz.end(), {p.x(), p.y(), p.z()});
  }
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    const int region = c->subdomain_index();
    if (region == 0) continue;
    for (int k = 0; k < 4; ++k) after.tets.push_back(id.at(c->vertex(k)));
    after.tet_region.push_back(region);
    // A facet on the outside of the domain is a boundary triangle.
    for (int k = 0; k < 4; ++k) {
      const auto n = c->neighbor(k);
      const int other = tr.is_infinite(n) ? 0 : n->subdomain_index();
      if (other != 0) continue;
      for (int j = 1; j <= 3; ++j) after.tris.push_back(id.at(c->vertex((k + j) % 4)));
      after.tri_surface.push_back(c->surface_patch_index(k));
    }
  }
  // Interfaces between two regions: written once, from the cell of the smaller region.
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    const int region = c->subdomain_index();
    if (region == 0) continue;
    for (int k = 0; k < 4; ++k) {
      const auto n = c->neighbor(k);
      if (tr.is_infinite(n)) continue;
      const int other = n->subdomain_index();
      if (other == 0 || other <= region) continue;
      for (int j = 1; j <= 3; ++j) after.tris.push_back(id.at(c->vertex((k + j) % 4)));
      after.tri_surface.push_back(c->surface_patch_index(k));
    }
  }
  classify_peer_vertices(m, after);
  verify_peer(m, after, "CGAL remeshing");
  m = std::move(after);
}

}  // namespace cvtmesh
