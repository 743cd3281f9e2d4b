// A flip pass over a 2D mesh: flip2d (the operator) driven by one acceptance test.
#pragma once
#include "core/mesh/tri_mesh2.h"
#include "core/quality/quality.h"

namespace cvtmesh {

enum class FlipCriterion2d {
  kDelaunay,  // flip edges that are not locally Delaunay (Lawson): the result is the CDT
  kQuality,   // flip edges whose flip raises the minimum quality of the two triangles
  kNoWorse,   // flip edges whose flip no quality row can see as a loss (flip2d_no_worse.h)
};

struct Flip2dPassOptions {
  FlipCriterion2d criterion = FlipCriterion2d::kDelaunay;
  Measure measure = Measure::kQ;  // for kQuality (larger = better)
  long max_flips = 0;             // safety cap; 0 = 100 * #T
};

// Flips every edge that is interior, not constrained (mesh.edges), between two triangles of the
// same surface, and asked for by the criterion, until no such edge remains (a stack of edges
// to re-examine, seeded with all of them). mesh.adj must be built. Returns the number of flips.
// Never inverts a triangle, never touches a constrained edge or moves a vertex.
long flip2d_pass(TriMesh2& mesh, const Flip2dPassOptions& options = {});

}  // namespace cvtmesh
