#include "core/pipeline/repair_slivers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "core/geometry/tet_geometry.h"
#include "core/geometry/vec3.h"
#include "core/mesh/build_adjacency.h"
#include "core/swap/local_mesh.h"
#include "core/mesh/walk_vertex_star.h"
#include "core/quality/element_time_step.h"
#include "core/quality/quality.h"
#include "core/quality/time_step_guard.h"
#include "core/swap/apply_swap.h"
#include "core/swap/compact_tets.h"
#include "core/swap/constrained_faces.h"
#include "core/swap/edge_ring.h"
#include "core/swap/flip23.h"
#include "core/swap/insert_vertex.h"
#include "core/swap/plan_adds_existing_simplex.h"
#include "core/swap/remove_edge.h"
#include "core/swap/swap_slivers.h"
#include "core/smoothing/nelder_mead_vertex.h"

namespace cvtmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kAngleScale = 60;  // degrees: min dihedral angle / 60 is compared with Q

const int* tet_of(const TetMesh& m, int t) {
  return &m.tets[4 * static_cast<std::size_t>(t)];
}

struct Score {
  double objective = kInf, q = kInf, angle = kInf;
  double max_angle = -kInf;  // the largest dihedral angle (degrees)
  double dt = kInf;          // the smallest element time step (changed_scores with a guard only)
};

Score tet_score_of(const double* const x[4]) {
  const std::array<double, 4> t = tet_table_qualities(x[0], x[1], x[2], x[3]);
  Score s;
  s.q = t[0];
  s.angle = t[2];
  s.max_angle = t[3];
  s.objective = std::min(s.q, s.angle / kAngleScale);
  return s;
}

Score tet_score(const TetMesh& m, const int* v) {
  const double* x[4] = {m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])};
  return tet_score_of(x);
}

void lower(Score& s, const Score& t) {
  s.objective = std::min(s.objective, t.objective);
  s.q = std::min(s.q, t.q);
  s.angle = std::min(s.angle, t.angle);
  s.max_angle = std::max(s.max_angle, t.max_angle);
  s.dt = std::min(s.dt, t.dt);
}

// The minima over the live tets of m.
Score mesh_score(const TetMesh& m) {
  Score s;
  for (int t = 0; t < m.nb_tets(); ++t)
    if (tet_of(m, t)[0] >= 0) lower(s, tet_score(m, tet_of(m, t)));
  return s;
}

// The neighbourhood of tet t copied for the attempt: t first, its unconstrained face neighbours,
// the rings of its edges (closed, at most 16 tets, of its region); then the unconstrained face
// neighbours of all these (room for an insertion's cavity to grow) and the stars of their free
// vertices (what the smoothing may change).
std::vector<int> neighbourhood(const TetMesh& mesh, const ConstrainedFaces& constrained, int t) {
  std::vector<int> s = tet_cavity(mesh, constrained, t);
  auto add = [&](int x) {
    if (mesh.tet_region[x] == mesh.tet_region[t] && std::find(s.begin(), s.end(), x) == s.end())
      s.push_back(x);
  };
  for (int e = 0; e < 6; ++e) {
    const EdgeRing r = edge_ring(mesh, t, e, 16);
    if (r.closed)
      for (int x : r.tets) add(x);
  }
  const std::size_t core = s.size();
  for (std::size_t i = 0; i < core; ++i) {
    const int* tv = tet_of(mesh, s[i]);
    for (int f = 0; f < 4; ++f) {
      const int behind = mesh.adj[4 * static_cast<std::size_t>(s[i]) + f];
      if (behind >= 0 &&
          !constrained.count(face_key(tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]])))
        add(behind / 4);
    }
    for (int k = 0; k < 4; ++k)
      if (mesh.vclass[tv[k]].dim == 3)
        for (int x : walk_vertex_star(mesh, s[i], tv[k])) add(x);
  }
  return s;
}

using Quad = std::array<int, 4>;

Quad sorted_quad(const int* v) {
  Quad q{v[0], v[1], v[2], v[3]};
  std::sort(q.begin(), q.end());
  return q;
}

// The minima over the tets that differ between the copy `before` and a candidate `after` (same
// vertex ids, maybe new ones appended): the tets of one that are not tets of the other, and the
// tets holding a vertex that moved. Everything else is the same in both.
std::pair<Score, Score> changed_scores(const TetMesh& before, const TetMesh& after, bool with_dt) {
  const int n0 = before.nb_vertices();
  std::vector<char> moved(static_cast<std::size_t>(after.nb_vertices()), 1);
  for (int v = 0; v < n0; ++v)
    moved[v] = !std::equal(before.point(v), before.point(v) + 3, after.point(v));
  auto quads = [](const TetMesh& m) {
    std::vector<Quad> q;
    for (int t = 0; t < m.nb_tets(); ++t)
      if (tet_of(m, t)[0] >= 0) q.push_back(sorted_quad(tet_of(m, t)));
    std::sort(q.begin(), q.end());
    return q;
  };
  const std::vector<Quad> qb = quads(before), qa = quads(after);
  auto side = [&](const TetMesh& m, const std::vector<Quad>& other) {
    Score s;
    for (int t = 0; t < m.nb_tets(); ++t) {
      const int* tv = tet_of(m, t);
      if (tv[0] < 0) continue;
      if (moved[tv[0]] || moved[tv[1]] || moved[tv[2]] || moved[tv[3]] ||
          !std::binary_search(other.begin(), other.end(), sorted_quad(tv))) {
        Score x = tet_score(m, tv);
        if (with_dt)
          x.dt = tet_time_step(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3]));
        lower(s, x);
      }
    }
    return s;
  };
  return {side(before, qa), side(after, qb)};
}

// Fixes (vclass.dim 2) the free vertices of m that are in none of the tets `ids`: the smoothing
// after an operation then moves only the vertices around what the operation changed.
void free_only_around(TetMesh& m, const std::vector<int>& ids) {
  std::vector<char> keep(static_cast<std::size_t>(m.nb_vertices()), 0);
  for (int t : ids)
    for (int k = 0; k < 4; ++k) keep[tet_of(m, t)[k]] = 1;
  for (int v = 0; v < m.nb_vertices(); ++v)
    if (!keep[v] && m.vclass[v].dim == 3) m.vclass[v].dim = 2;
}

// Max-min smoothing and Q flips on the copy, `rounds` times.
void local_polish(TetMesh& m, const RepairOptions& o) {
  SwapOptions so;
  so.measure = Measure::kQ;
  so.max_passes = 4;
  for (int r = 0; r < o.rounds; ++r) {
    smooth_maxmin3(m, o.smoothing);
    swap_slivers(m, so);
  }
}

// The candidate positions of a vertex inserted into tet t of m: its centroid, its circumcentre,
// the apex of the regular tet on each of its faces (on t's side), their mean.
std::vector<Vec3> insertion_points(const TetMesh& m, int t) {
  const int* v = tet_of(m, t);
  const double* x[4] = {m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])};
  std::vector<Vec3> pts;
  Vec3 centroid{0, 0, 0};
  for (const double* p : x) centroid = centroid + 0.25 * vec3(p);
  pts.push_back(centroid);
  pts.push_back(tet_circumcenter(x[0], x[1], x[2], x[3]));
  Vec3 mean{0, 0, 0};
  for (int f = 0; f < 4; ++f) {
    const double *a = x[kTetFace[f][0]], *b = x[kTetFace[f][1]], *c = x[kTetFace[f][2]];
    const Vec3 n = cross(sub(b, a), sub(c, a));  // outwards from t
    const double nn = norm(n);
    if (!(nn > 0)) continue;
    const double edge =
        (std::sqrt(dist2(a, b)) + std::sqrt(dist2(b, c)) + std::sqrt(dist2(c, a))) / 3;
    const Vec3 mid = (1.0 / 3) * (vec3(a) + vec3(b) + vec3(c));
    const Vec3 apex = mid - (edge * std::sqrt(2.0 / 3) / nn) * n;
    pts.push_back(apex);
    mean = mean + 0.25 * apex;
  }
  if (pts.size() == 6) pts.push_back(mean);
  return pts;
}

struct Candidate {
  TetMesh mesh;
  bool inserted = false;
  bool valid = false;
};

// The live tets of m holding vertex v (a local copy: a scan).
std::vector<int> star_of(const TetMesh& m, int v) {
  std::vector<int> star;
  for (int x = 0; x < m.nb_tets(); ++x) {
    const int* xv = tet_of(m, x);
    if (xv[0] >= 0 && std::find(xv, xv + 4, v) != xv + 4) star.push_back(x);
  }
  return star;
}

// The angle ceiling of to_mesh_extremes: min(angle_ceiling, the mesh's maximum at the start).
double extremes_ceiling(const RepairOptions& o, const Score& extremes) {
  return std::min(o.angle_ceiling, extremes.max_angle);
}

// The bounds of a simplex-search placement that replaces the tets `replaced` of m
// (to_mesh_extremes): the dihedral angles within [the mesh's minimum at the start, max(the replaced
// tets' maximum, extremes_ceiling)], the element time step, with the guard on, at least min(the
// replaced tets' smallest, the guard's floor) -- what the acceptance of a result asks of the tets
// it changes.
NelderMeadVertexOptions placement_bounds(const TetMesh& m, const std::vector<int>& replaced,
                                         const RepairOptions& o, const Score& extremes) {
  double max_angle = 0;
  for (int x : replaced) max_angle = std::max(max_angle, tet_score(m, tet_of(m, x)).max_angle);
  NelderMeadVertexOptions no;
  no.angle_scale = kAngleScale;
  no.angle_floor = extremes.angle;
  no.angle_ceiling = std::max(max_angle, extremes_ceiling(o, extremes));
  if (o.dt_guard.on)
    no.dt_floor = std::min(min_time_step(m, replaced.data(), replaced.data() + replaced.size()),
                           o.dt_guard.floor);
  return no;
}

// The copy m with vertex p inserted by plan, then the polish; with to_mesh_extremes the inserted
// vertex is then placed by the simplex search within placement_bounds.
Candidate inserted_candidate(const TetMesh& m, SwapPlan plan, const Vec3& at,
                             const RepairOptions& o, const Score& extremes) {
  Candidate c;
  c.mesh = m;
  const int p = c.mesh.nb_vertices();
  insert_vertex(c.mesh, plan, at.data());
  free_only_around(c.mesh, plan.new_ids);
  local_polish(c.mesh, o);
  if (o.to_mesh_extremes) {
    const std::vector<int> star = star_of(c.mesh, p);
    nelder_mead_vertex(c.mesh, p, star.data(), static_cast<int>(star.size()),
                       placement_bounds(m, plan.old_tets, o, extremes));
  }
  c.inserted = true;
  c.valid = true;
  return c;
}

// Insertion into tet t of the copy: the best (point, cavity) by the minimum of the new tets, then
// the polish (inserted_candidate); with every_placement, each (point, cavity) so (the caller
// judges them after their placement). The pairs tried: each point of insertion_points with the
// smallest cavity and with its Bowyer-Watson growth; the kernel centre of the smallest cavity
// with it, and the kernel centre of its growth from that centre with that growth.
std::vector<Candidate> try_insertion(const TetMesh& m, const ConstrainedFaces& constrained, int t,
                                     const RepairOptions& o, const Score& extremes) {
  std::vector<Candidate> all;
  SwapPlan best_plan;
  Vec3 best_p{};
  double best_min = -kInf;
  auto consider = [&](const Vec3& p, const std::vector<int>& cavity) {
    SwapPlan plan = plan_insert_vertex(m, cavity, p.data());
    if (plan.status != SwapStatus::kOk) return;
    if (o.every_placement) {
      all.push_back(inserted_candidate(m, std::move(plan), p, o, extremes));
      return;
    }
    // The new tets' minimum, with p in place (index nb_vertices).
    Score s;
    for (const auto& nt : plan.new_tets) {
      const double* x[4];
      for (int k = 0; k < 4; ++k) x[k] = nt[k] == m.nb_vertices() ? p.data() : m.point(nt[k]);
      lower(s, tet_score_of(x));
    }
    if (s.objective > best_min) {
      best_min = s.objective;
      best_plan = std::move(plan);
      best_p = p;
    }
  };
  const std::vector<int> small = tet_cavity(m, constrained, t);
  for (const Vec3& p : insertion_points(m, t)) {
    consider(p, small);
    std::vector<int> grown = small;
    grow_cavity(m, constrained, p.data(), grown, o.max_cavity);
    if (grown.size() > small.size()) consider(p, grown);
  }
  Vec3 centre;
  if (cavity_kernel_center(m, small, centre.data()) > 0) consider(centre, small);
  std::vector<int> grown = small;
  grow_cavity(m, constrained, centre.data(), grown, o.max_cavity);
  if (grown.size() > small.size() && cavity_kernel_center(m, grown, centre.data()) > 0)
    consider(centre, grown);
  if (best_min > -kInf)
    all.push_back(inserted_candidate(m, std::move(best_plan), best_p, o, extremes));
  return all;
}

// The interior vertices of tet t of the copy moved one after the other by the simplex search
// within the bounds (to_mesh_extremes).
Candidate try_moves(const TetMesh& m, int t, const RepairOptions& o, const Score& extremes) {
  Candidate c;
  c.mesh = m;
  for (int k = 0; k < 4; ++k) {
    const int v = tet_of(m, t)[k];
    if (m.vclass[v].dim != 3) continue;
    const std::vector<int> star = star_of(c.mesh, v);
    c.valid |= nelder_mead_vertex(c.mesh, v, star.data(), static_cast<int>(star.size()),
                                  placement_bounds(c.mesh, star, o, extremes))
                   .moved;
  }
  return c;
}

// A flip of tet t of the copy (edge removal of edge e < 6, or 2-3 flip of face e - 6), whatever
// it does to the minimum, then the polish.
Candidate try_flip(const TetMesh& m, const ConstrainedFaces& constrained, int t, int e,
                   const RepairOptions& o) {
  Candidate c;
  SwapPlan plan = e < 6 ? plan_remove_edge(m, constrained, t, e, Measure::kQ, 7)
                        : plan_flip23(m, constrained, t, e - 6);
  if (plan.status != SwapStatus::kOk || plan_adds_existing_simplex(m, plan)) return c;
  Score old_min;
  for (int x : plan.old_tets) lower(old_min, tet_score(m, tet_of(m, x)));
  c.mesh = m;
  apply_swap(c.mesh, plan);
  free_only_around(c.mesh, plan.new_ids);
  // A new tet that no smoothing can move and that is no better than the old minimum would most
  // likely stay and make the result be refused: not worth the polish.
  for (int x : plan.new_ids) {
    const int* xv = tet_of(c.mesh, x);
    if (c.mesh.vclass[xv[0]].dim < 3 && c.mesh.vclass[xv[1]].dim < 3 &&
        c.mesh.vclass[xv[2]].dim < 3 && c.mesh.vclass[xv[3]].dim < 3 &&
        tet_score(c.mesh, xv).objective <= old_min.objective + o.min_gain)
      return Candidate{};
  }
  local_polish(c.mesh, o);
  c.valid = true;
  return c;
}

}  // namespace

RepairStats repair_slivers(TetMesh& mesh, const RepairOptions& o) {
  if (o.max_tets < 0 || o.passes < 0 || o.rounds < 0 || o.max_cavity < 1)
    throw std::invalid_argument(
        "repair_slivers: max_tets, passes and rounds must be >= 0, max_cavity >= 1");
  if (mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);
  RepairStats stats;
  const Score start = mesh_score(mesh);
  stats.q_min_before = start.q;
  stats.angle_min_before = start.angle;
  const ConstrainedFaces constrained = constrained_faces(mesh);
  std::vector<int> free_slots;
  struct Entry {
    double objective;
    int t;
    std::array<int, 4> v;
  };
  std::vector<Entry> poor;
  // 1 + the last pass in which a committed result held the vertex (0: never). After the first
  // pass, a tet is tried again only if one of its vertices was in a committed result in the
  // previous pass (otherwise the attempt would see nearly the same neighbourhood and fail again).
  std::vector<int> touched(static_cast<std::size_t>(mesh.nb_vertices()), 0);
  for (int pass = 0; pass < o.passes; ++pass) {
    ++stats.passes;
    poor.clear();
    for (int t = 0; t < mesh.nb_tets(); ++t) {
      const int* tv = tet_of(mesh, t);
      if (tv[0] < 0) continue;
      if (pass > 0 && std::max(std::max(touched[tv[0]], touched[tv[1]]),
                               std::max(touched[tv[2]], touched[tv[3]])) < pass)
        continue;
      const Score s = tet_score(mesh, tv);
      if (s.q < o.q_below || s.angle < o.angle_below)
        poor.push_back({s.objective, t, {tv[0], tv[1], tv[2], tv[3]}});
    }
    std::sort(poor.begin(), poor.end(), [](const Entry& a, const Entry& b) {
      return a.objective != b.objective ? a.objective < b.objective : a.t < b.t;
    });
    if (static_cast<int>(poor.size()) > o.max_tets) poor.resize(o.max_tets);
    long committed = 0;
    for (const Entry& en : poor) {
      const int* tv = tet_of(mesh, en.t);
      if (!std::equal(en.v.begin(), en.v.end(), tv)) continue;  // changed by an earlier commit
      ++stats.nb_tried;
      const LocalMesh local =
          extract_local_mesh(mesh, constrained, neighbourhood(mesh, constrained, en.t));
      const ConstrainedFaces local_constrained = constrained_faces(local.mesh);
      // The best acceptable candidate (the first of equals, in a fixed order), judged on the
      // tets it changes: their minimum must rise (then the sorted qualities of the mesh rise
      // lexicographically and the global minima never fall).
      Candidate best;
      Score best_score;
      auto offer = [&](Candidate&& c) {
        if (!c.valid) return;
        const auto [was, now] = changed_scores(local.mesh, c.mesh, o.dt_guard.on);
        if (!time_step_allows(o.dt_guard, was.dt, now.dt)) return;
        if (!(now.objective > was.objective + o.min_gain) || now.q < was.q) return;
        // The angles of what changes: not below their minimum before (with to_mesh_extremes: the
        // mesh's minimum at the start), nor above max(their maximum before, extremes_ceiling).
        if (o.to_mesh_extremes
                ? now.angle < std::min(was.angle, start.angle) ||
                      now.max_angle > std::max(was.max_angle, extremes_ceiling(o, start))
                : now.angle < was.angle)
          return;
        if (!best.valid || now.objective > best_score.objective) {
          best = std::move(c);
          best_score = now;
        }
      };
      if (o.insert)
        for (Candidate& c : try_insertion(local.mesh, local_constrained, 0, o, start))
          offer(std::move(c));
      if (o.flip)
        for (int e = 0; e < 10; ++e) offer(try_flip(local.mesh, local_constrained, 0, e, o));
      if (o.to_mesh_extremes) offer(try_moves(local.mesh, 0, o, start));
      if (!best.valid) continue;
      if (!commit_local_mesh(mesh, local, best.mesh, &free_slots)) continue;
      ++committed;
      touched.resize(static_cast<std::size_t>(mesh.nb_vertices()), pass + 1);
      for (int v : local.global_vertex) touched[v] = pass + 1;
      if (best.inserted)
        ++stats.nb_inserted;
      else
        ++stats.nb_flip_smooth;
    }
    if (committed == 0) break;
  }
  compact_tets(mesh);
  const Score end = mesh_score(mesh);
  stats.q_min_after = end.q;
  stats.angle_min_after = end.angle;
  return stats;
}

}  // namespace cvtmesh
