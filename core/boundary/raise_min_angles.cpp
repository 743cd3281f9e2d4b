#include "core/boundary/raise_min_angles.h"

#include <algorithm>
#include <array>
#include <vector>

#include "core/boundary/boundary_fans.h"
#include "core/boundary/pattern_move.h"
#include "core/geometry/predicates.h"
#include "core/mesh/vertex_tets.h"
#include "core/quality/element_time_step.h"
#include "core/quality/quality.h"

namespace cvtmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

const int* tet_of(const TetMesh& m, int t) {
  return &m.tets[4 * static_cast<std::size_t>(t)];
}

std::array<double, 4> qualities(const TetMesh& m, int t) {
  const int* v = tet_of(m, t);
  return tet_table_qualities(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3]));
}

// The mover's star: its tets, per tet its maximum dihedral angle's bound (degrees), and the sum
// of their Q before the move (the floor of the sum after it).
struct Star {
  std::vector<int> tets;
  std::vector<double> ceiling;
  double q_sum = 0;
};

Star star_of(const TetMesh& mesh, const VertexTets& vt, int w, const AngleRaiseOptions& o) {
  Star s;
  s.tets.assign(vt.begin_of(w), vt.end_of(w));
  for (int t : s.tets) {
    const std::array<double, 4> q = qualities(mesh, t);
    s.ceiling.push_back(std::max(o.angle_ceiling, q[3]));
    s.q_sum += q[0];
  }
  return s;
}

// The star's minimum of min(smallest dihedral angle, target) with the mover where the mesh has it
// now, or -inf when a tet leaves the bounds or is not positively oriented, or the star's sum of Q
// falls.
double star_value(const TetMesh& mesh, const Star& s, const AngleRaiseOptions& o) {
  double value = o.target, q_sum = 0;
  for (std::size_t n = 0; n < s.tets.size(); ++n) {
    const int* v = tet_of(mesh, s.tets[n]);
    const double *a = mesh.point(v[0]), *b = mesh.point(v[1]), *c = mesh.point(v[2]),
                 *d = mesh.point(v[3]);
    if (orient3d(a, b, c, d) <= 0) return -kInf;
    const std::array<double, 4> q = tet_table_qualities(a, b, c, d);
    if (q[0] < o.q_floor || q[3] > s.ceiling[n]) return -kInf;
    if (o.dt_floor > 0 && tet_time_step(a, b, c, d) < o.dt_floor) return -kInf;
    value = std::min(value, q[2]);
    q_sum += q[0];
  }
  return q_sum < s.q_sum ? -kInf : value;
}

// The live tets below the target, lowest first (at most max_tets), and the mesh's smallest angle.
std::vector<std::pair<double, int>> low_tets(const TetMesh& mesh, const AngleRaiseOptions& o,
                                             double& lowest) {
  std::vector<std::pair<double, int>> low;
  lowest = kInf;
  for (int t = 0; t < mesh.nb_tets(); ++t) {
    if (tet_of(mesh, t)[0] < 0) continue;
    const double a = qualities(mesh, t)[2];
    lowest = std::min(lowest, a);
    if (a < o.target) low.push_back({a, t});
  }
  std::sort(low.begin(), low.end());
  return low;
}

}  // namespace

AngleRaiseStats raise_min_angles(TetMesh& mesh, const BoundaryModel& model,
                                 const AngleRaiseOptions& o) {
  AngleRaiseStats stats;
  std::vector<std::pair<double, int>> low = low_tets(mesh, o, stats.min_before);
  stats.min_after = stats.min_before;
  stats.nb_low = static_cast<long>(low.size());
  if (low.empty()) return stats;
  const VertexTets vt = vertex_tets(mesh);
  const BoundaryFans fans = model.geometry ? boundary_fans(mesh) : BoundaryFans{};
  PatternMoveOptions search = o.search;
  search.stop_at = o.target;
  for (int pass = 0; pass < o.passes && !low.empty(); ++pass) {
    if (static_cast<int>(low.size()) > o.max_tets) low.resize(o.max_tets);
    long moved_this_pass = 0;
    for (const auto& [unused, t] : low) {
      if (!(qualities(mesh, t)[2] < o.target)) continue;  // raised by an earlier tet's moves
      for (int k = 0; k < 4; ++k) {
        const int w = tet_of(mesh, t)[k];
        if (!may_move(mesh, model, w)) continue;
        const Star s = star_of(mesh, vt, w, o);
        if (!pattern_move(
                mesh, model, vt, fans, w, [&] { return star_value(mesh, s, o); }, search))
          continue;
        ++stats.nb_moved;
        ++moved_this_pass;
      }
    }
    if (moved_this_pass == 0) break;
    // stats.min_after stays the mesh's smallest angle: computed again after every pass that moved.
    low = low_tets(mesh, o, stats.min_after);
  }
  return stats;
}

}  // namespace cvtmesh
