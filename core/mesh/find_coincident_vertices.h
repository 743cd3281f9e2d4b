// Pairs of distinct vertices closer than a tolerance (relative to the bounding-box diagonal):
// coincident nodes of parts in contact, duplicated CAD points. TetGen merges or trips over them.
#pragma once
#include <array>
#include <vector>

namespace cvtmesh {

// xyz: #V by 3 coordinates. used: #V flags (empty: every vertex); only flagged vertices are
// compared. relative_tolerance: the distance, as a fraction of the bounding-box diagonal of the
// compared vertices, below which two vertices count as coincident (0: exact duplicates only).
// Returns the pairs (a < b, 0-based), sorted, at most max_pairs of them.
std::vector<std::array<int, 2>> find_coincident_vertices(const std::vector<double>& xyz,
                                                         const std::vector<char>& used,
                                                         double relative_tolerance = 1e-8,
                                                         int max_pairs = 1000);

}  // namespace cvtmesh
