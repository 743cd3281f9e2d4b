// The time-step guard of the polish (issue 16): an operation that replaces some tets by others (a
// vertex move changes its star, a flip its ring, a repair its local copy) is refused when
//  - the smallest element time step (element_time_step.h) of the new tets is below min(that of
//    the old tets, floor) -- like the Q guard of the flips (SwapOptions::guard_floor) -- or
//  - the smallest nodal time step (vertex_time_step.h) of the vertices whose K_jj or m_j change
//    falls below min(its old value, vertex_floor).
// The element step is a lower bound of the global explicit step, the nodal step an upper bound
// that the global step nearly equals when its largest mode sits at one vertex (measured: a
// guard on the element step alone let the polish lower the cube's global step by 6 %). floor =
// +inf: the smallest step may never fall; the polish sets the floors to a factor x the mesh's
// smallest steps before each iteration (time_step_guard). The accept sites (smooth_laplacian,
// smooth_maxmin3, swap_slivers, repair_slivers) call time_step_allows and VertexStepChange.
#pragma once
#include <limits>
#include <vector>

#include "core/mesh/tet_mesh.h"
#include "core/quality/vertex_time_step.h"

namespace cvtmesh {

struct TimeStepGuard {
  bool on = false;
  double floor = std::numeric_limits<double>::infinity();         // element steps
  double vertex_floor = std::numeric_limits<double>::infinity();  // nodal steps
};

// True when the guard is off or new_min >= min(old_min, guard.floor).
bool time_step_allows(const TimeStepGuard& guard, double old_min, double new_min);

// The smallest element time step of the given live tet ids (+inf for none).
double min_time_step(const TetMesh& mesh, const int* tet_ids, const int* tet_ids_end);

// The smallest element time step of the live tets of mesh (+inf for none).
double min_time_step(const TetMesh& mesh);

// The guard with floor = factor x the smallest element time step of the live tets of mesh and
// vertex_floor = factor x the smallest nodal time step.
TimeStepGuard time_step_guard(const TetMesh& mesh, double factor);

// The change of the nodal sums K_jj, m_j of an operation: add() the tets it removes with sign -1
// (at their old coordinates) and the tets it creates with +1, then allows() decides and apply()
// updates the sums once the operation is committed.
class VertexStepChange {
 public:
  void clear();
  // Tet of vertex ids v[0..3] at the points p[0..3].
  void add(const int* v, const double* const* p, double sign);
  // Tet v[0..3] at its coordinates in mesh.
  void add(const TetMesh& mesh, const int* v, double sign);
  // True when the guard is off or min over the changed vertices of their new nodal step is at
  // least min(their old minimum, guard.vertex_floor). Vertices beyond steps' size are new: their
  // old sums are 0.
  bool allows(const TimeStepGuard& guard, const VertexTimeSteps& steps) const;
  void apply(VertexTimeSteps& steps) const;  // grows steps for new vertices

 private:
  std::vector<int> ids_;
  std::vector<double> dk_, dm_;
};

}  // namespace cvtmesh
