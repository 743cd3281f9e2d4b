// The invariants every optimizer run must keep (checked at the end of each run, and by
// `cvtmesh check`): a violation is a bug and throws InvariantError.
#pragma once
#include <string>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/mesh/tri_mesh2.h"

namespace cvtmesh {

// After vs before: valid mesh (check_mesh: adjacency, no inverted/flat tet, boundary closed),
// the same constrained triangles (same vertex triples with the same coordinates and surface tags),
// fixed vertices unmoved, new vertices (if any) interior (class dim 3, every tet around them in
// the region of their class's entity), every region present with its volume (area in 2D) conserved
// to 1e-12 relative (compensated sums), every physical group present with the same name and
// entities and, for groups of the mesh's dimension, bounded by the same triangles (edges), the
// model's entities with the same boundaries, the point and line elements unchanged; and each
// surface whose triangles all turned one way around the volume (orient3d against the tet that
// holds them, of the lowest region tag for an interface) still does (a file's normals).
void verify_optimized(const TetMesh& before, const TetMesh& after);

// The same with a boundary that may move (the free-boundary optimization): boundary vertices are
// not required to stay put (core/boundary/verify_free_boundary.h checks where they went), each
// region's volume may change by up to `volume_tolerance` relative, and surface edge flips may
// change the triangles: each surface keeps its number of triangles and its vertices, each volume
// group is bounded by as many triangles of each surface as before.
// With boundary_collapses too (the surface coarsening: collapse_boundary_edges), a surface may
// lose vertices and triangles: each surface's vertices are a subset of its old ones, it keeps its
// Euler characteristic (V - E + F) and its boundary edges (those on one of its triangles), and
// each volume group loses as many triangles of each surface as that surface does.
struct VerifyOptions {
  bool boundary_moves = false;
  bool boundary_collapses = false;  // with boundary_moves only
  double volume_tolerance = 1e-12;
};
void verify_optimized(const TetMesh& before, const TetMesh& after, const VerifyOptions& options);
void verify_optimized(const TriMesh2& before, const TriMesh2& after);

// A moved boundary must not cross itself where the input's did not (issue 14's corpus: a boundary
// vertex moved on igl_armadillo's surface made two boundary triangles intersect, and `cvtmesh
// check` refused the output). Throws InvariantError naming the first pair of live boundary
// triangles of `after` that intersect improperly (exact: find_surface_intersections), unless the
// input's boundary already intersected itself (then the comparison says nothing).
void verify_no_new_surface_crossing(const TetMesh& before, const TetMesh& after);

// Volume of each region, indexed by region tag (sorted by tag); a compensated sum.
std::vector<std::pair<int, double>> region_volumes(const TetMesh& mesh);

}  // namespace cvtmesh
