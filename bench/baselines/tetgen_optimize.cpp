#include "bench/baselines/tetgen_optimize.h"

#include <tetgen.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "core/geometry/tetgen_library.h"
#include "core/geometry/predicates.h"
#include "core/mesh/build_adjacency.h"
#include "core/util/error.h"

namespace cvtmesh {

void tetgen_optimize(TetMesh& m, const TetgenOptimizeOptions& o) {
  tetgenio in, out;
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
  try {
    tetgen_library().tetrahedralize(sw.data(), &in, &out, nullptr, nullptr);
  } catch (int code) {
    throw InvariantError("TetGen -O failed (error code " + std::to_string(code) + ")");
  }
  if (out.numberofpoints < m.nb_vertices())
    throw InvariantError("TetGen -O changed the number of points (" +
                         std::to_string(m.nb_vertices()) + " -> " +
                         std::to_string(out.numberofpoints) + ")");
  const int nv = m.nb_vertices();
  for (int v = 0; v < nv; ++v)
    if (m.vclass[v].dim == 3)
      for (int d = 0; d < 3; ++d) m.xyz[3 * v + d] = out.pointlist[3 * v + d];
  // Points inserted by -q (interior only, -Y keeps the boundary mesh).
  const int region0 = m.tet_region.empty() ? 1 : m.tet_region[0];
  for (int v = nv; v < out.numberofpoints; ++v) {
    m.xyz.insert(m.xyz.end(), out.pointlist + 3 * v, out.pointlist + 3 * v + 3);
    m.vclass.push_back(VertexClass{3, region0});
    if (!m.node_tags.empty()) m.node_tags.push_back(0);
  }
  m.tets.clear();
  m.tet_region.clear();
  m.tet_tags.clear();
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    int v[4];
    for (int k = 0; k < 4; ++k) v[k] = out.tetrahedronlist[4 * t + k];
    if (orient3d(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])) < 0)
      std::swap(v[2], v[3]);
    m.tets.insert(m.tets.end(), v, v + 4);
    m.tet_region.push_back(out.numberoftetrahedronattributes > 0
                               ? static_cast<int>(out.tetrahedronattributelist[t])
                               : (m.tet_region.empty() ? 1 : m.tet_region[0]));
  }
  build_adjacency(m);
}

}  // namespace cvtmesh
