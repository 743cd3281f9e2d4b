// The decision, separate from the move: accept a planned swap only when the minimum quality of
// the new tets beats the minimum quality of the tets they replace by a small margin.
#pragma once
#include "core/mesh/tet_mesh.h"
#include "core/quality/quality.h"
#include "core/swap/swap_plan.h"

namespace cvtmesh {

struct SwapCriterion {
  // Larger is better: kQ (default), kRadiusRatio, kMinAngle (the dihedral criterion), kGmshIcn.
  Measure measure = Measure::kQ;
  // Required relative gain: new_min > old_min + min_gain * |old_min|. Strict even when 0, so
  // that a sequence of accepted swaps can never cycle.
  double min_gain = 1e-6;
};

// Throws std::invalid_argument for a measure where larger is not better (kMaxAngle).
void check_swap_measure(Measure m);

// Minimum quality of the given tets (vertex quadruples) in measure m.
double min_quality(const TetMesh& mesh, const std::vector<std::array<int, 4>>& tets, Measure m);
// Minimum quality of the given live tet ids in measure m.
double min_quality(const TetMesh& mesh, const std::vector<int>& tet_ids, Measure m);

// True if plan is valid (status kOk) and its new tets' minimum quality beats the old ones'.
// Uses plan.old_min/new_min when they were computed in the criterion's measure.
bool accept_swap(const TetMesh& mesh, const SwapPlan& plan, const SwapCriterion& criterion);
// The same decision from the two minima: new_min above accept_floor(old_min, criterion).
bool accept_swap(double old_min, double new_min, const SwapCriterion& criterion);
// The value a plan's new minimum must exceed to be accepted (old_min + min_gain |old_min|): a
// planner may skip every candidate at or below it.
double accept_floor(double old_min, const SwapCriterion& criterion);

}  // namespace cvtmesh
