#include "bench/baselines/tetgen_optimize.h"

#include <tetgen.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/delaunay/tetrahedralize_isolated.h"
#include "core/geometry/predicates.h"
#include "core/mesh/build_adjacency.h"
#include "core/util/error.h"

namespace cvtmesh {

void tetgen_optimize(TetMesh& m, const TetgenOptimizeOptions& o) {
  tetgenio in;
  in.firstnumber = 0;
  in.numberofpoints = m.nb_vertices();
  in.pointlist = new REAL[m.xyz.size()];
  std::copy(m.xyz.begin(), m.xyz.end(), in.pointlist);
  std::vector<int> live;
  for (int t = 0; t < m.nb_tets(); ++t)
    if (m.tets[4 * t] >= 0) live.push_back(t);
  in.numberoftetrahedra = static_cast<int>(live.size());
  in.numberofcorners = 4;
  in.tetrahedronlist = new int[4 * live.size()];
  in.numberoftetrahedronattributes = 1;
  in.tetrahedronattributelist = new REAL[live.size()];
  for (std::size_t i = 0; i < live.size(); ++i) {
    const int* v = &m.tets[4 * live[i]];
    // TetGen's orientation is the opposite of ours.
    in.tetrahedronlist[4 * i + 0] = v[0];
    in.tetrahedronlist[4 * i + 1] = v[1];
    in.tetrahedronlist[4 * i + 2] = v[3];
    in.tetrahedronlist[4 * i + 3] = v[2];
    in.tetrahedronattributelist[i] = m.tet_region[live[i]];
  }
  in.numberoftrifaces = m.nb_tris();
  in.trifacelist = new int[m.tris.size()];
  in.trifacemarkerlist = new int[m.nb_tris()];
  std::copy(m.tris.begin(), m.tris.end(), in.trifacelist);
  std::copy(m.tri_surface.begin(), m.tri_surface.end(), in.trifacemarkerlist);
  std::string sw = std::getenv("CVTMESH_TETGEN_VERBOSE")
                       ? "rq1.414YAzVO"
                       : "rq1.414YAzQO" + std::to_string(o.level) + "/" + std::to_string(o.flags);
  // In a child process (core/delaunay/tetrahedralize_isolated.h): a crash inside TetGen cannot
  // take `compare` or `bench` down; it becomes an InvariantError, the column's failure.
  const IsolatedTetgenOutput out =
      tetrahedralize_isolated(sw.data(), in, "TetGen's own optimizer (-r -q -O), a baseline");
  const int nb_out = static_cast<int>(out.points.size() / 3);
  if (nb_out < m.nb_vertices())
    throw InvariantError("TetGen -O changed the number of points (" +
                         std::to_string(m.nb_vertices()) + " -> " + std::to_string(nb_out) + ")");
  const int nv = m.nb_vertices();
  for (int v = 0; v < nv; ++v)
    if (m.vclass[v].dim == 3)
      for (int d = 0; d < 3; ++d) m.xyz[3 * v + d] = out.points[3 * v + d];
  // Points inserted by -q (interior only, -Y keeps the boundary mesh).
  const int region0 = m.tet_region.empty() ? 1 : m.tet_region[0];
  for (int v = nv; v < nb_out; ++v) {
    m.xyz.insert(m.xyz.end(), out.points.begin() + 3 * v, out.points.begin() + 3 * v + 3);
    m.vclass.push_back(VertexClass{3, region0});
    if (!m.node_tags.empty()) m.node_tags.push_back(0);
  }
  m.tets.clear();
  m.tet_region.clear();
  m.tet_tags.clear();
  const int nt = static_cast<int>(out.tets.size() / 4);
  for (int t = 0; t < nt; ++t) {
    int v[4];
    for (int k = 0; k < 4; ++k) v[k] = out.tets[4 * t + k];
    if (orient3d(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])) < 0)
      std::swap(v[2], v[3]);
    m.tets.insert(m.tets.end(), v, v + 4);
    m.tet_region.push_back(static_cast<std::size_t>(t) < out.attributes.size()
                               ? static_cast<int>(out.attributes[t])
                               : region0);
  }
  build_adjacency(m);
}

}  // namespace cvtmesh
