#include "core/swap/swap_slivers.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <cstdint>
#include <vector>

#include <unordered_map>
#include <unordered_set>

#include "core/mesh/build_adjacency.h"
#include "core/mesh/face_key.h"
#include "core/swap/accept_swap.h"
#include "core/swap/apply_swap.h"
#include "core/swap/compact_tets.h"
#include "core/swap/constrained_faces.h"
#include "core/swap/edge_ring.h"
#include "core/swap/flip23.h"
#include "core/swap/plan_adds_existing_simplex.h"
#include "core/swap/remove_edge.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

double quality_of(const TetMesh& mesh, int t, Measure m) {
  const int* v = &mesh.tets[4 * static_cast<std::size_t>(t)];
  return tet_quality(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]), mesh.point(v[3]), m);
}

double global_min(const std::vector<double>& q, const TetMesh& mesh) {
  double m = std::numeric_limits<double>::infinity();
  for (int t = 0; t < mesh.nb_tets(); ++t)
    if (mesh.tets[4 * static_cast<std::size_t>(t)] >= 0) m = std::min(m, q[t]);
  return m;
}

// Local index (into kTetEdge) of the edge (a, b) of tet tv, -1 if it is not one.
int local_edge(const int* tv, int a, int b) {
  int ia = -1, ib = -1;
  for (int k = 0; k < 4; ++k) {
    if (tv[k] == a) ia = k;
    if (tv[k] == b) ib = k;
  }
  if (ia < 0 || ib < 0) return -1;
  for (int e = 0; e < 6; ++e)
    if ((kTetEdge[e][0] == ia && kTetEdge[e][1] == ib) ||
        (kTetEdge[e][0] == ib && kTetEdge[e][1] == ia))
      return e;
  return -1;
}

}  // namespace

SwapStats swap_slivers(TetMesh& mesh, const SwapOptions& options) {
  check_swap_measure(options.measure);
  if (options.max_ring < 3 || options.max_ring > 7)
    throw std::invalid_argument("swap_slivers: max_ring must be 3..7");
  if (options.max_passes < 0) throw std::invalid_argument("swap_slivers: max_passes must be >= 0");
  if (mesh.adj.size() != mesh.tets.size()) build_adjacency(mesh);

  const Measure measure = options.measure;
  const SwapCriterion criterion{measure, options.min_gain};
  const ConstrainedFaces constrained = constrained_faces(mesh);
  // Edges of constrained triangles can never be removed (a face around them is constrained); only
  // an edge between two vertices of constrained triangles can be one.
  std::unordered_set<EdgeKey, EdgeKeyHash> constrained_edges;
  std::vector<char> on_constraint(mesh.nb_vertices(), 0);
  for (int f = 0; f < mesh.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      constrained_edges.insert(edge_key(mesh.tris[3 * f + k], mesh.tris[3 * f + (k + 1) % 3]));
      on_constraint[mesh.tris[3 * f + k]] = 1;
    }
  // Operations planned and refused, per tet slot: bit e (0..5) for the removal of edge e, bit
  // 6 + f for the 2-3 flip of face f. A refusal is marked on every tet of the cavity (the same
  // operation seen from each of them); when a swap creates tets, the marks of their edges and
  // faces are cleared on every tet around them (those cavities changed). So an operation is
  // planned again only after its cavity changed: the refusal would be the same (vertices never
  // move and the decision depends on the cavity only).
  std::vector<std::uint16_t> refused;
  auto clear_around = [&](int t) {
    const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
    for (int e = 0; e < 6; ++e) {
      const EdgeRing ring = edge_ring(mesh, t, e, 1 << 20);
      for (int r : ring.tets) {
        const int le = local_edge(&mesh.tets[4 * static_cast<std::size_t>(r)], tv[kTetEdge[e][0]],
                                  tv[kTetEdge[e][1]]);
        if (le >= 0) refused[r] &= static_cast<std::uint16_t>(~(1u << le));
      }
    }
    for (int f = 0; f < 4; ++f) {
      const int o = mesh.adj[4 * static_cast<std::size_t>(t) + f];
      if (o >= 0) refused[o / 4] &= static_cast<std::uint16_t>(~(1u << (6 + o % 4)));
    }
  };
  SwapStats stats;

  // Per-slot quality and version (bumped whenever the slot's tet changes).
  std::vector<double> q(static_cast<std::size_t>(mesh.nb_tets()));
  std::vector<unsigned> version(q.size(), 0);
  refused.assign(q.size(), 0);
  std::vector<int> free_slots;
  const int nt0 = mesh.nb_tets();
#pragma omp parallel for schedule(static, 1024) if (nt0 > 1024)
  for (int t = 0; t < nt0; ++t)
    if (mesh.tets[4 * static_cast<std::size_t>(t)] >= 0) q[t] = quality_of(mesh, t, measure);
  for (int t = 0; t < nt0; ++t) {
    if (mesh.tets[4 * static_cast<std::size_t>(t)] < 0) {
      free_slots.push_back(t);
      continue;
    }
    ++stats.nb_tets_before;
  }
  stats.min_before = global_min(q, mesh);
  double sum_reference = 0;  // the mean quality at the start (sum_criterion)
  if (options.sum_criterion && stats.nb_tets_before > 0) {
    for (int t = 0; t < mesh.nb_tets(); ++t)
      if (mesh.tets[4 * static_cast<std::size_t>(t)] >= 0) sum_reference += q[t];
    sum_reference /= static_cast<double>(stats.nb_tets_before);
  }

  struct Entry {
    double q;
    int t;
    unsigned version;
  };
  std::vector<Entry> order;
  // 1 + the pass in which a tet containing the vertex was last replaced or created (0: never).
  // Every operation
  // tried on a tet none of whose vertices changed since the previous pass was tried then, on the
  // same cavity, and refused: such tets are not tried again (the same result, without the work).
  std::vector<int> touched(mesh.nb_vertices(), 0);
  auto touch = [&](int t, int pass) {
    for (int k = 0; k < 4; ++k) touched[mesh.tets[4 * static_cast<std::size_t>(t) + k]] = pass;
  };
  // The nodal sums of the time-step guard, updated at each committed swap.
  VertexTimeSteps dt_steps;
  if (options.dt_guard.on) dt_steps = vertex_time_steps(mesh);
  VertexStepChange dt_change;
  auto nodal_change = [&](const SwapPlan& plan,
                          VertexStepChange& change) -> const VertexStepChange& {
    change.clear();
    for (int o : plan.old_tets) change.add(mesh, &mesh.tets[4 * static_cast<std::size_t>(o)], -1);
    for (const auto& t : plan.new_tets) change.add(mesh, t.data(), +1);
    return change;
  };
  // One tet's evaluation: every operation on it planned, the best the criterion accepts, and the
  // refusal marks to set (bit e: the removal of edge e, 6 + f: the 2-3 flip of face f, on every
  // tet of the operation's cavity). Reads the mesh, q and refused only.
  struct Evaluation {
    bool valid = false;
    bool have_best = false;
    double best_gain = 0;
    SwapPlan best;
    std::vector<std::pair<int, std::uint16_t>> marks;
    // With the time-step guard: the vertices whose nodal sums it read, and its buffer.
    std::vector<int> reads;
    VertexStepChange change;
  };
  auto evaluate = [&](int t, Evaluation& ev) {
    ev.have_best = false;
    ev.best_gain = 0;
    ev.marks.clear();
    ev.reads.clear();
    const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
    // Evaluates a valid plan; true if the criterion accepts it (it becomes best if better).
    auto consider = [&](SwapPlan&& plan) {
      if (plan.status != SwapStatus::kOk) return false;
      if (!plan.quality_known || plan.measure != measure) {
        plan.old_min = std::numeric_limits<double>::infinity();
        for (int o : plan.old_tets) plan.old_min = std::min(plan.old_min, q[o]);
        // Without the sum criterion a plan is accepted only above accept_floor(old_min): the
        // new tets' qualities stop at the first one at or below it (refused either way).
        const double floor = options.sum_criterion ? -std::numeric_limits<double>::infinity()
                                                   : accept_floor(plan.old_min, criterion);
        plan.new_min = std::numeric_limits<double>::infinity();
        for (const auto& n : plan.new_tets) {
          plan.new_min =
              std::min(plan.new_min, tet_quality(mesh.point(n[0]), mesh.point(n[1]),
                                                 mesh.point(n[2]), mesh.point(n[3]), measure));
          if (plan.new_min <= floor) break;
        }
        plan.quality_known = true;
        plan.measure = measure;
      }
      double gain = 0;
      if (options.sum_criterion) {
        if (plan.new_min < plan.old_min) return false;
        double old_sum = 0, new_sum = 0;
        for (int o : plan.old_tets) old_sum += q[o];
        for (const auto& n : plan.new_tets)
          new_sum += tet_quality(mesh.point(n[0]), mesh.point(n[1]), mesh.point(n[2]),
                                 mesh.point(n[3]), measure);
        // Against the mesh's mean: the average rises when the sum gains more than the mean
        // times the change in the number of tets.
        gain = new_sum - old_sum -
               sum_reference * (static_cast<double>(plan.new_tets.size()) -
                                static_cast<double>(plan.old_tets.size()));
        if (!(gain > options.sum_gain)) return false;
      } else if (!accept_swap(plan.old_min, plan.new_min, criterion)) {
        return false;
      }
      if (options.use_guard) {
        const double guard_old = min_quality(mesh, plan.old_tets, options.guard_measure);
        const double guard_new = min_quality(mesh, plan.new_tets, options.guard_measure);
        if (guard_new < std::min(guard_old, options.guard_floor)) return false;
      }
      if (options.dt_guard.on &&
          !time_step_allows(options.dt_guard, min_quality(mesh, plan.old_tets, Measure::kTimeStep),
                            min_quality(mesh, plan.new_tets, Measure::kTimeStep)))
        return false;
      if (options.dt_guard.on) {
        for (int o : plan.old_tets)
          ev.reads.insert(ev.reads.end(), &mesh.tets[4 * static_cast<std::size_t>(o)],
                          &mesh.tets[4 * static_cast<std::size_t>(o)] + 4);
        if (!nodal_change(plan, ev.change).allows(options.dt_guard, dt_steps)) return false;
      }
      // Topologically valid too (a folded boundary can make positive tets that would repeat an
      // edge or a face of the mesh): checked only for the plans accepted so far.
      if (plan_adds_existing_simplex(mesh, plan)) return false;
      if (options.sum_criterion ? !ev.have_best || gain > ev.best_gain
                                : !ev.have_best || plan.new_min > ev.best.new_min) {
        ev.best = std::move(plan);
        ev.best_gain = gain;
        ev.have_best = true;
      }
      return true;
    };
    if (options.remove_edges)
      for (int e = 0; e < 6; ++e) {
        if (refused[t] >> e & 1) continue;
        const int a = tv[kTetEdge[e][0]], b = tv[kTetEdge[e][1]];
        if (on_constraint[a] && on_constraint[b] && constrained_edges.count(edge_key(a, b)))
          continue;
        const EdgeRing ring = edge_ring(mesh, t, e, options.max_ring);
        if (!ring.closed) continue;
        // The planner searches only the triangulations the criterion could accept
        // (1M tets, `cvtmesh optimize`: the polish's flips 1.3 -> 1.0 s an iteration).
        double floor = -std::numeric_limits<double>::infinity();
        if (!options.sum_criterion) {
          double old_min = std::numeric_limits<double>::infinity();
          for (int o : ring.tets) old_min = std::min(old_min, q[o]);
          floor = accept_floor(old_min, criterion);
        }
        if (!consider(plan_remove_edge(mesh, constrained, ring, measure, floor)))
          for (int r : ring.tets) {
            const int le = local_edge(&mesh.tets[4 * static_cast<std::size_t>(r)], a, b);
            if (le >= 0) ev.marks.push_back({r, static_cast<std::uint16_t>(1u << le)});
          }
      }
    if (options.flip23)
      for (int f = 0; f < 4; ++f) {
        if (refused[t] >> (6 + f) & 1) continue;
        const int behind = mesh.adj[4 * static_cast<std::size_t>(t) + f];
        if (behind < 0) continue;
        if (!consider(plan_flip23(mesh, constrained, t, f))) {
          ev.marks.push_back({t, static_cast<std::uint16_t>(1u << (6 + f))});
          ev.marks.push_back({behind / 4, static_cast<std::uint16_t>(1u << (6 + behind % 4))});
        }
      }
  };
  std::vector<Evaluation> evals;
  Evaluation serial;
  // Per vertex, the stamp of the last chunk in which a tet containing it was removed or created.
  std::vector<int> vmod(mesh.nb_vertices(), 0);
  int stamp = 0;
  for (int pass = 0; pass < options.max_passes; ++pass) {
    order.clear();
    for (int t = 0; t < mesh.nb_tets(); ++t) {
      const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
      if (tv[0] < 0 || !(q[t] < options.quality_threshold)) continue;
      if (pass > 0 && std::max(std::max(touched[tv[0]], touched[tv[1]]),
                               std::max(touched[tv[2]], touched[tv[3]])) < pass)
        continue;
      order.push_back({q[t], t, version[t]});
    }
    std::sort(order.begin(), order.end(),
              [](const Entry& a, const Entry& b) { return a.q != b.q ? a.q < b.q : a.t < b.t; });
    ++stats.passes;
    long nb_done = 0;
    // The entries in chunks: each chunk's tets are evaluated in parallel against the mesh as it
    // is at the chunk's start, then taken in order, serially: an evaluation is used only if no
    // tet containing one of its tet's vertices was removed or created since (every tet it read,
    // the edge rings and the face neighbours, contains two or three of them, and the refusal
    // marks it skipped were cleared only around new tets): it is then exactly what the serial
    // evaluation would give at that point; otherwise the tet is evaluated again there. Same
    // result as one serial loop, for any number of threads. With the time-step guard the nodal
    // sums it read, at the vertices of every cavity it tried, must not have changed either.
    const std::size_t chunk = 4096;
    for (std::size_t c0 = 0; c0 < order.size(); c0 += chunk) {
      const std::size_t c1 = std::min(order.size(), c0 + chunk);
      ++stamp;
      const int chunk_stamp = stamp;
      {
        evals.resize(c1 - c0);
#pragma omp parallel for schedule(dynamic, 64) if (c1 - c0 > 64)
        for (std::ptrdiff_t i = static_cast<std::ptrdiff_t>(c0);
             i < static_cast<std::ptrdiff_t>(c1); ++i) {
          Evaluation& ev = evals[i - c0];
          ev.valid = false;
          const Entry& en = order[i];
          if (mesh.tets[4 * static_cast<std::size_t>(en.t)] < 0 || version[en.t] != en.version)
            continue;
          try {
            evaluate(en.t, ev);
            ev.valid = true;
          } catch (...) {
            // Evaluated again in order below, where the error is thrown as in the serial loop.
          }
        }
      }
      for (std::size_t i = c0; i < c1; ++i) {
        const Entry& en = order[i];
        const int t = en.t;
        if (mesh.tets[4 * static_cast<std::size_t>(t)] < 0 || version[t] != en.version) continue;
        const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
        Evaluation* ev = &evals[i - c0];
        bool stale = !ev->valid || std::max(std::max(vmod[tv[0]], vmod[tv[1]]),
                                            std::max(vmod[tv[2]], vmod[tv[3]])) >= chunk_stamp;
        for (std::size_t k = 0; k < ev->reads.size() && !stale; ++k)
          stale = vmod[ev->reads[k]] >= chunk_stamp;
        if (stale) {
          ev = &serial;
          evaluate(t, serial);
        }
        ++stats.nb_tried;
        for (const auto& [slot, bits] : ev->marks) refused[slot] |= bits;
        if (!ev->have_best) continue;
        SwapPlan& best = ev->best;

        const std::size_t nb_old = best.old_tets.size(), nb_new = best.new_tets.size();
        // The new tets' vertices are the old ones'.
        for (int o : best.old_tets) {
          ++version[o];
          touch(o, pass + 1);
          for (int k = 0; k < 4; ++k) vmod[mesh.tets[4 * static_cast<std::size_t>(o) + k]] = stamp;
        }
        if (options.dt_guard.on) nodal_change(best, dt_change).apply(dt_steps);
        apply_swap(mesh, best, &free_slots);
        if (q.size() < static_cast<std::size_t>(mesh.nb_tets())) {
          q.resize(static_cast<std::size_t>(mesh.nb_tets()));
          version.resize(q.size(), 0);
          refused.resize(q.size(), 0);
        }
        for (int id : best.new_ids) refused[id] = 0;
        for (int id : best.new_ids) clear_around(id);
        for (int id : best.new_ids) {
          ++version[id];
          touch(id, pass + 1);
          q[id] = quality_of(mesh, id, measure);
        }
        ++nb_done;
        if (nb_old == 2 && nb_new == 3) {
          ++stats.nb_flip23;
        } else {
          ++stats.nb_by_ring[nb_old];
          if (nb_old == 3)
            ++stats.nb_flip32;
          else
            ++stats.nb_edge_removals;
        }
      }
    }
    if (nb_done == 0) break;
  }

  stats.min_after = global_min(q, mesh);
  if (options.compact) compact_tets(mesh);
  for (int t = 0; t < mesh.nb_tets(); ++t)
    if (mesh.tets[4 * static_cast<std::size_t>(t)] >= 0) ++stats.nb_tets_after;
  return stats;
}

}  // namespace cvtmesh
