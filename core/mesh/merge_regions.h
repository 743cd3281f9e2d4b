// Puts an optimized submesh (extract_regions) back into its parent: the parent's unselected tets
// stay as they were, in their order and with their tags, followed by the submesh's tets; the
// parent's vertices keep their ids (the sub's pinned ones did not move), vertices the
// optimization added are appended; the parent's triangles stay, the sub's replace those it
// carried. The sub's node_tags must be those extract_regions set (i + 1; 0 for a new vertex).
#pragma once
#include "core/mesh/extract_regions.h"

namespace cvtmesh {

// Throws InvariantError if the sub lost a vertex or moved a pinned one.
void merge_regions(TetMesh& parent, const RegionSubmesh& extracted, const TetMesh& optimized);

// The same for several disjoint parts extracted from the same parent (extract_tets), put back at
// once: the tets no part selected first, then each part's in the order given; the vertices each
// part added appended part after part. With boundary_moved, a part may have changed the parent's
// triangles it carried (a free boundary: vertices moved on their surfaces, surface edges flipped):
// those are replaced by the part's (the parent's other triangles first, in order, then each
// part's), and a part may have removed some of its surface vertices (the coarsening: they stay
// in the parent, in no element, for the caller to drop), never a pinned one; without it they
// must come back the same. Either way the faces a part had on its
// interface with the others (extract_tets' added faces) must come back exactly, or the parts
// would not fit together: InvariantError.
void merge_parts(TetMesh& parent, const std::vector<const RegionSubmesh*>& extracted,
                 const std::vector<const TetMesh*>& optimized, bool boundary_moved = false);

}  // namespace cvtmesh
