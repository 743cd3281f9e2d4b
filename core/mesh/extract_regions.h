// The part of a tet mesh made of some of its regions (volume entities), as a mesh of its own, to
// optimize alone: its vertices shared with the other regions (the interface) are pinned as
// corners (marked entity < 0, pin_vertices' encoding), its boundary faces are all constrained
// triangles (the interface's included). merge_regions puts the result back.
#pragma once
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct RegionSubmesh {
  TetMesh mesh;  // the selected tets, in the parent's order; node_tags[i] = i + 1 (see merge)
  std::vector<int> to_parent;            // #V_sub: the parent vertex of each sub vertex
  std::vector<std::size_t> parent_tags;  // #V_sub: the parent's node tags (empty if it had none)
  std::vector<char> selected_tet;        // #T_parent: 1 for a tet of the selection
  std::vector<char> selected_tri;        // #F_parent: 1 for a triangle carried by the sub
  int nb_interface = 0;                  // vertices pinned (shared with the other regions)
  int nb_added_faces = 0;  // boundary faces of the sub that had no triangle (added, dropped back)
};

// The tets of mesh whose tet_region is in `regions` (sorted or not). The parent's extra element
// blocks come along where all their nodes are in the sub (the others' nodes in the sub are
// pinned); entities, groups and periodic links are copied.
RegionSubmesh extract_regions(const TetMesh& mesh, const std::vector<int>& regions);

// The same for any selection of tets (selected[t] != 0; #T entries): a part of a partition
// (core/distributed/), whose interface with the other parts is pinned the same way.
RegionSubmesh extract_tets(const TetMesh& mesh, const std::vector<char>& selected);

}  // namespace cvtmesh
