// One step of the non-smooth ascent of max-min smoothing (Freitag & Ollivier-Gooch 1997), shared
// by the interior vertices (smooth_maxmin3) and the boundary ones (smooth_boundary_maxmin, where
// the vertex moves within its surface's tangent plane or along its curve's tangent line): the
// direction is the smallest vector of the convex hull of the gradients of the nearly active
// candidates (within a band of the minimum, at most 8), all of which rise along it; the step
// length is where the linearised minimum meets another candidate's linearisation, at most
// max_step. The caller's line search halves it until its own acceptance test holds.
#pragma once
#include <utility>
#include <vector>

#include "core/geometry/vec3.h"

namespace cvtmesh {

// Where a vertex may move: anywhere (kFree), within the plane normal to `axis` (kPlane), along
// the line of `axis` (kLine); axis is a unit vector.
struct TangentSpace {
  enum Kind { kFree, kPlane, kLine } kind = kFree;
  Vec3 axis{0, 0, 0};
  // The component of g in the space.
  Vec3 project(const Vec3& g) const {
    if (kind == kPlane) return g - dot(g, axis) * axis;
    if (kind == kLine) return dot(g, axis) * axis;
    return g;
  }
};

struct AscentStep {
  Vec3 direction{0, 0, 0};
  double alpha = 0;  // step length along `direction` (the move is alpha * direction)
  bool ok = false;   // false: no common ascent direction (a local max-min optimum)
};

// candidates: (value, gradient) of every function of the objective and of the guards (a guard
// shifted so that at its bound it is as active as the minimum); fmin: the objective's current
// minimum; max_step: the longest move (a distance). The gradients are projected on `space` first
// (in place).
AscentStep maxmin_ascent_step(std::vector<std::pair<double, Vec3>>& candidates, double fmin,
                              double max_step, const TangentSpace& space = {});

}  // namespace cvtmesh
