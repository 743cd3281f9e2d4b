#include "core/boundary/restore_crossing_vertices.h"

#include <vector>

#include "core/boundary/restore_boundary_vertices.h"
#include "core/mesh/find_surface_intersections.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {

RestoreCrossingStats restore_crossing_vertices(TetMesh& mesh, const TetMesh& input,
                                               int max_rounds) {
  RestoreCrossingStats st;
  const std::vector<int> tris = live_boundary_tris(mesh);
  auto crossings = find_surface_intersections(mesh.xyz, tris, 1000);
  st.nb_pairs_before = st.nb_pairs_after = static_cast<long>(crossings.size());
  if (crossings.empty() ||
      !find_surface_intersections(input.xyz, live_boundary_tris(input), 1).empty())
    return st;
  const VertexTets star = vertex_tets(mesh);
  for (int round = 0; round <= max_rounds && !crossings.empty(); ++round) {
    ++st.rounds;
    // The vertices of the crossing triangles, then `round` rings of boundary neighbours.
    std::vector<int> seeds;
    for (const auto& pair : crossings)
      for (int f : pair)
        for (int k = 0; k < 3; ++k) seeds.push_back(tris[3 * f + k]);
    st.nb_restored += restore_vertices_to_input(
        mesh, input, star, boundary_rings(mesh.nb_vertices(), tris, seeds, round));
    crossings = find_surface_intersections(mesh.xyz, tris, 1000);
  }
  st.nb_pairs_after = static_cast<long>(crossings.size());
  return st;
}

}  // namespace cvtmesh
