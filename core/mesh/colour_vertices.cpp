#include "core/mesh/colour_vertices.h"

namespace cvtmesh {

VertexColouring colour_vertices(
    int nb_vertices, const std::vector<int>& order,
    const std::function<void(int v, std::vector<int>& out)>& conflicts) {
  std::vector<int> colour(static_cast<std::size_t>(nb_vertices), -1);
  std::vector<int> mark;  // mark[c] == v: colour c is taken by a conflict of v
  std::vector<int> near;
  int nb_colours = 0;
  for (int v : order) {
    near.clear();
    conflicts(v, near);
    for (int w : near)
      if (w != v && colour[w] >= 0) mark[colour[w]] = v;
    int c = 0;
    while (c < nb_colours && mark[c] == v) ++c;
    if (c == nb_colours) mark.push_back(-1), ++nb_colours;
    colour[v] = c;
  }
  VertexColouring k;
  k.offset.assign(static_cast<std::size_t>(nb_colours) + 1, 0);
  for (int v : order) ++k.offset[colour[v] + 1];
  for (int c = 0; c < nb_colours; ++c) k.offset[c + 1] += k.offset[c];
  k.vertices.resize(order.size());
  std::vector<int> fill(k.offset.begin(), k.offset.end() - 1);
  for (int v : order) k.vertices[fill[colour[v]]++] = v;
  return k;
}

}  // namespace cvtmesh
