// The pattern search of one vertex on its entity, shared by the last stages of a free-boundary run
// that raise a star's value within bounds (raise_nodal_steps.h: the lowest nodal time steps;
// raise_min_angles.h: the smallest dihedral angles). Mover w steps along fixed directions -- the
// coordinate axes and the cube's diagonals for an interior vertex, six directions of its fan's
// tangent plane for a surface vertex, the two ways along its curve's tangent for a curve vertex --
// a boundary position projected onto w's entity of the reference geometry and checked by
// plan_boundary_move (orientation, folds) and fan_within_tolerance (Hausdorff); the step halves
// where no direction raises the value. The caller's `value` reads the mesh with w where the search
// put it (-inf: out of its bounds). The end is kept only if it raises the start's value and, for a
// boundary vertex, the volume budget admits it (charged); otherwise w goes back.
#pragma once
#include <functional>
#include <limits>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/volume_budget.h"
#include "core/geometry/boundary_geometry.h"
#include "core/geometry/vec3.h"
#include "core/mesh/tet_mesh.h"
#include "core/mesh/vertex_tets.h"

namespace cvtmesh {

struct PatternMoveOptions {
  double hausdorff = std::numeric_limits<double>::infinity();  // absolute
  VolumeBudget* volume_budget = nullptr;  // if set, boundary moves stay within it (charged)
  int max_evaluations = 200;              // positions evaluated at most
  double initial_step = 0.25;  // the first step: this fraction of the mover's shortest star edge
  double final_step = 1e-3;    // the search stops below this fraction of it
  double stop_at = std::numeric_limits<double>::infinity();  // the search ends at this value
  // An interior mover's further directions, tried only in a round where none of the fixed ones
  // raises the value (given the search's smallest step length, an absolute distance); none if
  // empty (raise_nodal_steps.h: the gradient's directions).
  std::function<std::vector<Vec3>(double final_length)> extra_directions;
};

// The search directions of mover w (above; none for a curve whose tangent cannot be found).
std::vector<Vec3> move_directions(const TetMesh& mesh, const BoundaryModel& model,
                                  const BoundaryFans& fans, int w, double len);

// Whether w may move: an interior vertex of vclass.dim 3, or a boundary vertex the model lets
// move (with a geometry).
bool may_move(const TetMesh& mesh, const BoundaryModel& model, int w);

// Moves w by the pattern search; true when the move was kept. `vt`: the stars (coordinates only
// change), `fans` the boundary fans (may be empty without a geometry).
bool pattern_move(TetMesh& mesh, const BoundaryModel& model, const VertexTets& vt,
                  const BoundaryFans& fans, int w, const std::function<double()>& value,
                  const PatternMoveOptions& options);

}  // namespace cvtmesh
