// The structural defects that break a constrained Delaunay rebuild (TetGen): boundary or
// interface triangles that intersect (core/mesh/find_surface_intersections.h) and coincident or
// near-coincident vertices (core/mesh/find_coincident_vertices.h). optimize() checks for them
// before any method that rebuilds the tetrahedralization and then uses local operations only;
// `cvtmesh check` reports them.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct StructuralDefects {
  std::vector<std::array<int, 2>> intersecting_tris;    // pairs of constrained triangle indices
  std::vector<std::array<int, 2>> coincident_vertices;  // pairs of vertex ids (used by a tet)
  bool empty() const { return intersecting_tris.empty() && coincident_vertices.empty(); }
  // One line per kind, naming the first few occurrences: coordinates, node tags, surface tags,
  // e.g. "2 pairs of boundary triangles intersect (first: triangle 12 of surface 3 and triangle
  // 40 of surface 5, near (0.5, 0.5, 0))".
  std::vector<std::string> describe(const TetMesh& mesh) const;
};

// relative_tolerance: vertices closer than this fraction of the bounding-box diagonal are
// reported as coincident. Only vertices used by a live tet or a constrained triangle count.
StructuralDefects find_structural_defects(const TetMesh& mesh, double relative_tolerance = 1e-8);

}  // namespace cvtmesh
