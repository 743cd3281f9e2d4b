// Independent sets of vertices for parallel vertex moves: a greedy colouring in a given order, so
// that no two vertices of one colour conflict (share a tet, or whatever else the caller's moves
// read of each other). The vertices of a colour then move concurrently, each reading and writing
// only its own neighbourhood, and the result does not depend on the number of threads.
#pragma once
#include <functional>
#include <vector>

namespace cvtmesh {

struct VertexColouring {
  // #colours+1 offsets: colour c holds vertices[offset[c] .. offset[c+1]-1], in the order given.
  std::vector<int> offset;
  std::vector<int> vertices;

  int nb_colours() const { return offset.empty() ? 0 : static_cast<int>(offset.size()) - 1; }
  int size_of(int c) const { return offset[c + 1] - offset[c]; }
  const int* begin_of(int c) const { return vertices.data() + offset[c]; }
  const int* end_of(int c) const { return vertices.data() + offset[c + 1]; }
};

// Colours `order` (distinct vertex ids in [0, nb_vertices)) greedily in that order, each vertex
// the smallest colour that none of its already coloured conflicts has. conflicts(v, out) appends
// the vertices that conflict with v (duplicates, v itself and vertices outside `order` are
// allowed); the relation must be symmetric. Deterministic; O(sum of the conflict lists).
VertexColouring colour_vertices(int nb_vertices, const std::vector<int>& order,
                                const std::function<void(int v, std::vector<int>& out)>& conflicts);

}  // namespace cvtmesh
