// Re-places the mid-edge nodes of an order-2 input (tet10, tri6, line3) on the edges of its
// optimized corner mesh, for the writers (gmsh_model.cpp writes order-2 elements from it).
#pragma once
#include <cstdint>
#include <functional>
#include <string>

#include "core/mesh/mesh_data.h"
#include "core/mesh/mid_edge_nodes.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// Projects p (3 doubles) onto entity (dim, tag) of the model (dim 1: a curve, 2: a surface) into
// out; false if it has no geometry for that entity (the node is then placed without it).
using MidEdgeProjector = std::function<bool(int dim, int tag, const double* p, double* out)>;

// One node on every edge of mesh's live tets, triangles and kept lines / triangles
// (mesh.model.extra, Gmsh types 1 and 2), from mesh.model.high_order (order 2):
//  - an edge of the input whose two corners did not move (same node tags, same coordinates):
//    the input's node, tag and position (a convert, or a fixed boundary, keeps them all);
//  - a boundary edge (an edge of a line on a curve, else of a triangle on a surface) that project
//    knows: the straight midpoint projected on that curve / surface (the CAD, through Gmsh);
//  - a boundary edge of the input otherwise: the straight midpoint plus the input node's offset
//    from the input edge's midpoint (the input's curvature, carried along);
//  - anything else (interior edges, new edges): the straight midpoint.
// Then every tet is checked (tet10_positive); a tet that fails gets its curved nodes put back on
// their straight midpoints, and its neighbours are checked again (nb_fallback); a tet that fails
// even straight is counted in nb_invalid. Without `fallback`, nothing is straightened and
// nb_invalid counts the tets that fail as placed (cvtmesh check: a file's own inverted tet10s).
// Tags are the input's where the edge is the input's (0 otherwise: the writer gives fresh ones).
MidEdgePlacement place_mid_edge_nodes(const TetMesh& mesh, const MidEdgeProjector& project = {},
                                      bool fallback = true);

// The same for a planar triangle mesh (tri6, line3): one node on every edge of mesh's live
// triangles and segments (mesh.edges, on their curves), by the same rules, a segment's edge
// being the boundary edge (projected on its curve, or the input's offset carried); an edge is
// the input's unmoved one when its corners' x and y are the input's, and every node placed here
// lies in the mesh's plane z = z0 (a kept node keeps the input's coordinates). Then every
// triangle is checked (tri6_positive), with the same fallback and counts.
MidEdgePlacement place_mid_edge_nodes(const TriMesh2& mesh, const MidEdgeProjector& project = {},
                                      bool fallback = true);

// The placement for data's mesh (3D or 2D, as above, with the fallback), stored in
// data.model().high_order.placed, where the writers take it while the coordinates are these.
const MidEdgePlacement& place_mid_edge_nodes(MeshData& data, const MidEdgeProjector& project = {});

// A hash of the mesh's coordinates: a placement is used only for the coordinates it was made for.
std::uint64_t mid_edge_fingerprint(const TetMesh& mesh);
std::uint64_t mid_edge_fingerprint(const TriMesh2& mesh);

// One line for the summary: "order-2 mesh: N mid-edge nodes re-placed: ... kept, ... on the CAD,
// ... straight (... because a curved node would invert an element)".
std::string mid_edge_summary(const MidEdgePlacement& p);

}  // namespace cvtmesh
