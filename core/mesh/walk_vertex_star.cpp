#include "core/mesh/walk_vertex_star.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace cvtmesh {

std::vector<int> walk_vertex_star(const TetMesh& mesh, int t, int v) {
  auto holds = [&](int s) {
    const int* sv = &mesh.tets[4 * static_cast<std::size_t>(s)];
    return sv[0] == v || sv[1] == v || sv[2] == v || sv[3] == v;
  };
  if (t < 0 || t >= mesh.nb_tets() || mesh.tets[4 * static_cast<std::size_t>(t)] < 0 || !holds(t))
    throw std::invalid_argument("walk_vertex_star: tet " + std::to_string(t) +
                                " is not a live tet holding vertex " + std::to_string(v));
  std::vector<int> star = {t};
  for (std::size_t i = 0; i < star.size(); ++i) {
    const int s = star[i];
    const int* sv = &mesh.tets[4 * static_cast<std::size_t>(s)];
    for (int f = 0; f < 4; ++f) {
      if (sv[f] == v) continue;  // the face opposite v does not hold it
      const int behind = mesh.adj[4 * static_cast<std::size_t>(s) + f];
      if (behind < 0) continue;
      const int n = behind / 4;
      if (std::find(star.begin(), star.end(), n) == star.end()) star.push_back(n);
    }
  }
  return star;
}

}  // namespace cvtmesh
