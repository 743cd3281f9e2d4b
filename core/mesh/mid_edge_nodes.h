// An order-2 mesh's mid-edge nodes (Gmsh tet10, tri6, line3). They are not vertices of the mesh:
// the optimizer works on the corner (order-1) mesh, and the writers re-place one node on every
// edge of the mesh they write (core/io/place_mid_edge_nodes.h).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh/vertex_class.h"

namespace cvtmesh {

// Where the nodes of one written mesh go, edge by edge (place_mid_edge_nodes).
struct MidEdgePlacement {
  std::vector<int> edges;          // #M by 2 vertex ids (0-based, smaller first), sorted by pair
  std::vector<std::size_t> tags;   // #M: the input's node tag for that edge, or 0 (a new edge)
  std::vector<double> xyz;         // #M by 3
  std::vector<VertexClass> where;  // #M: the entity the node lies on (curve, surface or volume)
  std::uint64_t fingerprint = 0;   // mid_edge_fingerprint of the mesh it was placed for
  // How each node was placed (they add up to #M).
  int nb_kept = 0;      // the input's node, unchanged (both corners unmoved)
  int nb_cad = 0;       // projected on the model's CAD curve or surface (through Gmsh)
  int nb_curved = 0;    // discrete boundary: the straight midpoint plus the input's offset
  int nb_straight = 0;  // the straight midpoint (interior edges, new edges, no geometry)
  // Nodes put back on the straight midpoint because a curved position inverted an element
  // (counted in nb_straight too), and elements still not positive with straight edges.
  int nb_fallback = 0;
  int nb_invalid = 0;
};

struct MidEdgeNodes {
  int order = 1;  // 2: the mesh is written with order-2 elements (tet10, tri6, line3)
  // The input's mid-edge nodes, #N, by the Gmsh node tags of their edge's corners.
  std::vector<std::size_t> corner_tags;  // #N by 2 (smaller first)
  std::vector<double> corner_xyz;        // #N by 6: the two corners' input coordinates
  std::vector<std::size_t> tags;         // #N: the node's Gmsh tag
  std::vector<double> xyz;               // #N by 3: the node's input coordinates
  // The placement for the mesh to write; used while its fingerprint matches the mesh.
  MidEdgePlacement placed;
};

}  // namespace cvtmesh
