// The smallest vector of the convex hull of a few 3-vectors: the steepest common ascent direction
// of functions with these gradients (every one rises along it at least as fast as its squared
// length), the step of non-smooth max-min ascents (smooth_maxmin3, the insertion's kernel centre).
#pragma once
#include <vector>

#include "core/geometry/vec3.h"

namespace cvtmesh {

// The point of the convex hull of g[0..n-1] (n >= 1) nearest the origin, or zero when the origin
// is in it (or nearly, relative to the largest |g|^2). The minimum lies on a face of at most three
// points (in 3D, if it is not the origin): O(n^3) candidates, for a handful of vectors.
Vec3 min_norm_in_hull(const std::vector<Vec3>& g);

}  // namespace cvtmesh
