#include "core/boundary/restore_hausdorff_vertices.h"

#include <vector>

#include "core/boundary/boundary_hausdorff.h"
#include "core/boundary/restore_boundary_vertices.h"
#include "core/boundary/triangle_set_distance.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {
namespace {

// The vertices of the triangles where the bound is broken, on either side.
std::vector<int> offending_vertices(const TetMesh& mesh, const std::vector<int>& tris,
                                    const BoundaryGeometry& g, double bound) {
  std::vector<int> seeds;
  const int nf = static_cast<int>(tris.size() / 3);
  for (int f = 0; f < nf; ++f) {
    double s[10][3];
    const int* v = &tris[3 * f];
    triangle_samples(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), s);
    for (const auto& p : s)
      if (g.distance_to_boundary(p) > bound) {
        seeds.insert(seeds.end(), v, v + 3);
        break;
      }
  }
  const std::vector<double> ref = g.samples();
  if (!ref.empty()) {
    const TriangleSetDistance now(mesh.xyz, tris);
    for (std::size_t i = 0; i + 2 < ref.size(); i += 3) {
      double q[3];
      const int f = now.closest_triangle(&ref[i], q);
      if (f < 0) continue;
      const double d2 = (q[0] - ref[i]) * (q[0] - ref[i]) +
                        (q[1] - ref[i + 1]) * (q[1] - ref[i + 1]) +
                        (q[2] - ref[i + 2]) * (q[2] - ref[i + 2]);
      if (d2 > bound * bound) seeds.insert(seeds.end(), &tris[3 * f], &tris[3 * f] + 3);
    }
  }
  return seeds;
}

}  // namespace

RestoreHausdorffStats restore_hausdorff_vertices(TetMesh& mesh, const TetMesh& input,
                                                 const BoundaryGeometry& reference, double bound,
                                                 int max_rounds) {
  RestoreHausdorffStats st;
  st.before = st.after = boundary_hausdorff(mesh, reference).value();
  if (st.before <= bound) return st;
  const std::vector<int> tris = live_boundary_tris(mesh);
  const VertexTets star = vertex_tets(mesh);
  for (int round = 0; round <= max_rounds && st.after > bound; ++round) {
    ++st.rounds;
    const std::vector<int> seeds = offending_vertices(mesh, tris, reference, bound);
    st.nb_restored += restore_vertices_to_input(
        mesh, input, star, boundary_rings(mesh.nb_vertices(), tris, seeds, round));
    st.after = boundary_hausdorff(mesh, reference).value();
  }
  return st;
}

}  // namespace cvtmesh
