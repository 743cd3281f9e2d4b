// Edges looked up by vertex: a flat replacement for a hash set of edge keys where most vertices
// are on no edge of the set (a planar mesh's constrained edges: boundary and interfaces).
#pragma once
#include <vector>

namespace cvtmesh {

class EdgeIndex {
 public:
  EdgeIndex() = default;
  // edges: #E by 2 vertex ids in [0, nb_vertices) (0-based; either order; repeats allowed).
  EdgeIndex(const std::vector<int>& edges, int nb_vertices);
  // The id e (0..#E-1) of the first edge {u, w} of the list, taken either way; -1 if none.
  int find(int u, int w) const {
    if (u < 0 || u + 1 >= static_cast<int>(start_.size())) return -1;
    for (int k = start_[u]; k < start_[u + 1]; ++k)
      if (other_[k] == w) return edge_[k];
    return -1;
  }
  bool contains(int u, int w) const { return find(u, w) >= 0; }

 private:
  std::vector<int> start_;  // #V + 1: vertex u's entries are [start_[u], start_[u + 1])
  std::vector<int> other_;  // the other end of each entry's edge
  std::vector<int> edge_;   // its id, entries of one vertex in increasing id
};

}  // namespace cvtmesh
