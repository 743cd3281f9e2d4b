#include "bench/baselines/cgal_mesh3.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/Mesh_polyhedron_3.h>
#include <CGAL/make_mesh_3.h>

#include <array>
#include <cmath>
#include <set>
#include <unordered_map>
#include <vector>

#include "core/mesh/build_adjacency.h"
#include "core/mesh/check_mesh.h"
#include "core/util/error.h"

namespace cvtmesh {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Mesh_polyhedron_3<K>::type;
using Domain = CGAL::Polyhedral_mesh_domain_with_features_3<K>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

double mean_boundary_edge(const TetMesh& m) {
  double sum = 0;
  long n = 0;
  for (int f = 0; f < m.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      const double* a = m.point(m.tris[3 * f + k]);
      const double* b = m.point(m.tris[3 * f + (k + 1) % 3]);
      sum += std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                       (a[2] - b[2]) * (a[2] - b[2]));
      ++n;
    }
  return n ? sum / static_cast<double>(n) : 0;
}

}  // namespace

void cgal_mesh3(TetMesh& m, const CgalMesh3Options& o) {
  std::set<int> regions(m.tet_region.begin(), m.tet_region.end());
  if (regions.size() != 1)
    throw InvariantError("CGAL Mesh_3 baseline: " + std::to_string(regions.size()) +
                         " regions (the polyhedral domain has one)");
  // The boundary surface as a soup of its own vertices (no interior vertex: the polyhedron
  // must not hold isolated vertices), oriented consistently.
  std::vector<K::Point_3> points;
  std::vector<int> local(m.nb_vertices(), -1);
  std::vector<std::vector<std::size_t>> faces;
  for (int f = 0; f < m.nb_tris(); ++f) {
    std::vector<std::size_t> face;
    for (int k = 0; k < 3; ++k) {
      const int v = m.tris[3 * f + k];
      if (local[v] < 0) {
        local[v] = static_cast<int>(points.size());
        points.emplace_back(m.xyz[3 * v], m.xyz[3 * v + 1], m.xyz[3 * v + 2]);
      }
      face.push_back(static_cast<std::size_t>(local[v]));
    }
    faces.push_back(face);
  }
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, faces);
  Polyhedron poly;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, poly);
  Domain domain(poly);
  domain.detect_features(o.feature_angle);
  const double h = o.size > 0 ? o.size : mean_boundary_edge(m);
  const double d = o.facet_distance > 0 ? o.facet_distance : h / 10;
  namespace P = CGAL::parameters;
  Criteria criteria(P::edge_size = h, P::facet_angle = o.facet_angle, P::facet_size = h,
                    P::facet_distance = d, P::cell_radius_edge_ratio = o.radius_edge_ratio,
                    P::cell_size = h);
  const C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, P::odt(), P::perturb(), P::exude());

  TetMesh out;
  const int region = *regions.begin();
  std::unordered_map<Tr::Vertex_handle, int> id;
  auto vid = [&](Tr::Vertex_handle v) {
    const auto it = id.find(v);
    if (it != id.end()) return it->second;
    const int n = out.nb_vertices();
    id[v] = n;
    const auto& p = v->point();
    out.xyz.insert(out.xyz.end(),
                   {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    out.vclass.push_back(VertexClass{3, region});
    return n;
  };
  for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    for (int k = 0; k < 4; ++k) out.tets.push_back(vid(c->vertex(k)));
    out.tet_region.push_back(region);
  }
  for (auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f) {
    const auto c = f->first;
    const int i = f->second;
    int tri[3];
    for (int j = 0; j < 3; ++j) {
      tri[j] = vid(c->vertex((i + 1 + j) % 4));
      out.vclass[tri[j]] = VertexClass{2, 1};
    }
    out.tris.insert(out.tris.end(), tri, tri + 3);
    out.tri_surface.push_back(1);
  }
  out.node_tags.assign(out.nb_vertices(), 0);
  build_adjacency(out);
  const MeshCheck chk = check_mesh(out);
  if (!chk.ok)
    throw InvariantError("CGAL Mesh_3 returned an invalid mesh: " +
                         (chk.problems.empty() ? std::string("?") : chk.problems.front()));
  m = std::move(out);
}

}  // namespace cvtmesh
