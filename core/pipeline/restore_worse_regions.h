// The per-region "never worse than the input" of optimize(): where an optimized mesh has
// elements worse than the input's worst (element_shortfall > 0 against the input's statistics:
// lower Q, lower minimum or higher maximum angle), the vertices around them go back to their
// input positions. Round k takes the vertices of the elements still short and k rings of
// neighbours around them; a vertex goes back only if every element of its star stays positively
// oriented (exact orient3d / orient2d) and the star's summed shortfall does not rise. A vertex of
// a short element that cannot go back (or was not moved, or is new) is, if interior, moved part
// of the way back (a half, a quarter, an eighth) or towards the centroid of its star's other
// vertices, then by a compass search (axis steps from a quarter of its star's shortest edge,
// halved), wherever that lowers its star's shortfall, with the same orientation test. Last,
// whole neighbourhoods (the short elements' vertices and 1..2*max_rounds rings) go back at once
// where that lowers their summed shortfall. So the mesh's
// total shortfall never rises and no element is inverted. Connectivity never changes; a boundary
// vertex moves only all the way back to its input position (the caller verifies the boundary).
// Serial, in vertex order: the result depends on the input only.
#pragma once
#include "core/mesh/tet_mesh.h"
#include "core/mesh/tri_mesh2.h"
#include "core/quality/quality_stats.h"

namespace cvtmesh {

struct RestoreOptions {
  int max_rounds = 8;  // rings of neighbours: 0 .. max_rounds-1
  // The partial moves' coordinates are rounded to this many significant digits (as a text
  // writer stores them; 0 = not rounded). The full restores are the input's own coordinates.
  int digits = 16;
};

struct RestoreStats {
  long nb_short_before = 0;  // elements short of the reference before / after
  long nb_short_after = 0;
  long nb_restored = 0;  // vertices moved back to their input positions
  long nb_smoothed = 0;  // vertices moved part of the way back, towards their star's centroid or
                         // by the compass search
  int rounds = 0;
};

// `mesh`'s vertices v < input.nb_vertices() are `input`'s vertex v (optimize keeps the ids).
RestoreStats restore_worse_regions(TetMesh& mesh, const TetMesh& input, const QualityStats& ref,
                                   const RestoreOptions& options = {});
RestoreStats restore_worse_regions(TriMesh2& mesh, const TriMesh2& input, const QualityStats& ref,
                                   const RestoreOptions& options = {});

}  // namespace cvtmesh
