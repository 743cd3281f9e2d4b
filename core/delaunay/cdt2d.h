// Constrained Delaunay triangulation of planar points and segments, with exact predicates
// (incremental insertion with Lawson flips inside a super-triangle, segment recovery by flips,
// Delaunay restoration by flips away from the segments).
#pragma once
#include <vector>

namespace cvtmesh {

struct Cdt2dResult {
  int nb_points = 0;       // #V input points; ids #V, #V+1, #V+2 are the super-triangle's
  std::vector<double> xy;  // (#V+3) by 2: the input points, then the super-triangle's vertices
  std::vector<int> tris;   // #T by 3 vertex ids, counter-clockwise, covering the super-triangle
  std::vector<int> adj;    // 3*#T packed adjacency adj[3t+e] = 3t'+e' (TriMesh2 convention)
  // #T: -1 for triangles reachable from the super-triangle's vertices without crossing a segment
  // (outside), otherwise the id (0..nb_components-1) of the part enclosed by segments.
  std::vector<int> component;
  int nb_components = 0;
  std::vector<int> segments;  // #S by 2: the input segments, split at input points lying on them
};

// xy: #V by 2 coordinates; segments: #S by 2 vertex ids (0-based), edges that must appear.
// Every non-segment edge between two triangles is locally Delaunay (cocircular ties broken
// arbitrarily). With no segments, every triangle is outside (component -1): the result is the
// Delaunay triangulation of the points plus the super-triangle's vertices.
// Throws InputError for a duplicated point, a vertex id out of range, a zero-length segment or
// two segments that cross.
Cdt2dResult cdt2d(const std::vector<double>& xy, const std::vector<int>& segments);

// cdt2d(xy, segments) and cdt2d(xy, {}) (the Delaunay triangulation of the points) from one
// insertion of the points, which does not depend on the segments: the same two results as the
// two calls. Throws as cdt2d.
void cdt2d_and_delaunay(const std::vector<double>& xy, const std::vector<int>& segments,
                        Cdt2dResult& constrained, Cdt2dResult& delaunay);

}  // namespace cvtmesh
