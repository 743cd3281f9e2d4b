#include "core/mesh/check_mesh.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "core/geometry/predicates.h"
#include "core/mesh/check_surface_mesh.h"
#include "core/mesh/face_key.h"

namespace cvtmesh {
namespace {

void problem(MeshCheck& r, const std::string& msg) {
  r.ok = false;
  if (r.problems.size() < 40) r.problems.push_back(msg);
}

}  // namespace

int last_non_positive_tet(const TetMesh& m) {
  const int nt = m.nb_tets();
  int bad = -1;
#pragma omp parallel for schedule(static, 1024) reduction(max : bad) if (nt > 1024)
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tets[4 * t];
    if (tv[0] >= 0 && orient3d(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])) <= 0)
      bad = std::max(bad, t);
  }
  return bad;
}

MeshCheck check_mesh(const TetMesh& m) {
  if (is_surface_mesh(m)) return check_surface_mesh(m);
  MeshCheck r;
  const int nv = m.nb_vertices(), nt = m.nb_tets();
  if (static_cast<int>(m.tet_region.size()) != nt) problem(r, "tet_region size differs from #T");
  if (static_cast<int>(m.tri_surface.size()) != m.nb_tris())
    problem(r, "tri_surface size differs from #F");
  if (static_cast<int>(m.vclass.size()) != nv) problem(r, "vclass size differs from #V");
  if (m.adj.size() != m.tets.size()) {
    problem(r, "adjacency not built (adj size differs from 4*#T)");
    return r;
  }
  // The constrained triangles, indexed; only a face whose three vertices are all on some
  // constrained triangle can be one (no hashing of the other faces).
  std::unordered_map<FaceKey, int, FaceKeyHash> constrained;
  std::vector<char> on_constraint(nv, 0);
  for (int f = 0; f < m.nb_tris(); ++f) {
    const int* fv = &m.tris[3 * f];
    for (int k = 0; k < 3; ++k)
      if (fv[k] < 0 || fv[k] >= nv) {
        problem(r, "triangle " + std::to_string(f) + " has a vertex id out of range");
        return r;
      }
    constrained.emplace(face_key(fv[0], fv[1], fv[2]), static_cast<int>(constrained.size()));
    for (int k = 0; k < 3; ++k) on_constraint[fv[k]] = 1;
  }
  // How many live tets have each constrained triangle as a face, and how many of those have no
  // tet behind it: 1 and 1 on the boundary, 2 and 0 on an interface; anything else is two tets
  // overlapping on it (or unlinked).
  std::vector<int> holders(constrained.size(), 0), open_holders(constrained.size(), 0);
  // Orientation, the costly part, in parallel (a flag per tet: the report stays in tet order).
  std::vector<char> positive(nt, 1);
#pragma omp parallel for schedule(static, 1024) if (nt > 1024)
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tets[4 * t];
    bool in_range = tv[0] >= 0;
    for (int k = 0; k < 4 && in_range; ++k) in_range = tv[k] >= 0 && tv[k] < nv;
    if (in_range)
      positive[t] = orient3d(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])) > 0;
  }
  auto constraint_of = [&](const int* tv, int f) {
    const int a = tv[kTetFace[f][0]], b = tv[kTetFace[f][1]], c = tv[kTetFace[f][2]];
    if (!on_constraint[a] || !on_constraint[b] || !on_constraint[c]) return -1;
    const auto it = constrained.find(face_key(a, b, c));
    return it == constrained.end() ? -1 : it->second;
  };
  // A parallel pass finds the tets with any problem (and which constrained triangles are faces);
  // the report is then written in tet order from those only.
  auto same_face = [&](const int* tv, int f, int t2, int f2) {
    // t2's vertex opposite the face is none of the face's three, which are all t2's.
    const int* tv2 = &m.tets[4 * t2];
    for (int k = 0; k < 3; ++k) {
      const int a = tv[kTetFace[f][k]];
      if (a == tv2[f2] || (a != tv2[0] && a != tv2[1] && a != tv2[2] && a != tv2[3])) return false;
    }
    return true;
  };
  // Two positively oriented tets sharing a face lie on its two sides exactly when they list it
  // in opposite cyclic orders (kTetFace orients every face the same way around its tet): a
  // combinatorial test, no predicate (not made next to an inverted tet, reported as such).
  auto opposite_sides = [&](const int* tv, int f, int t2, int f2) {
    const int* tv2 = &m.tets[4 * t2];
    const int a[3] = {tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]]};
    const int b[3] = {tv2[kTetFace[f2][0]], tv2[kTetFace[f2][1]], tv2[kTetFace[f2][2]]};
    for (int i = 0; i < 3; ++i)
      if (b[i] == a[0]) return b[(i + 1) % 3] == a[2] && b[(i + 2) % 3] == a[1];
    return false;
  };
  std::vector<char> suspect(nt, 0);
#pragma omp parallel for schedule(static, 1024) if (nt > 1024)
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tets[4 * t];
    if (tv[0] < 0) continue;
    bool in_range = true;
    for (int k = 0; k < 4; ++k) in_range = in_range && tv[k] >= 0 && tv[k] < nv;
    if (!in_range || !positive[t]) {
      suspect[t] = 1;
      if (!in_range) continue;
    }
    for (int f = 0; f < 4; ++f) {
      const int ci = constraint_of(tv, f);
      const int o = m.adj[4 * t + f];
      if (ci >= 0) {
        std::atomic_ref<int>(holders[ci]).fetch_add(1, std::memory_order_relaxed);
        if (o < 0) std::atomic_ref<int>(open_holders[ci]).fetch_add(1, std::memory_order_relaxed);
      }
      if (o < 0) {
        if (ci < 0) suspect[t] = 1;
        continue;
      }
      const int t2 = o / 4, f2 = o % 4;
      if (o >= 4 * nt || m.tets[4 * t2] < 0 || m.adj[o] != 4 * t + f || !same_face(tv, f, t2, f2) ||
          (positive[t] && positive[t2] && !opposite_sides(tv, f, t2, f2)) ||
          (m.tet_region[t] != m.tet_region[t2] && ci < 0))
        suspect[t] = 1;
    }
  }
  for (int t = 0; t < nt; ++t) {
    if (!suspect[t]) continue;
    const int* tv = &m.tets[4 * t];
    bool in_range = true;
    for (int k = 0; k < 4; ++k)
      if (tv[k] < 0 || tv[k] >= nv) in_range = false;
    if (!in_range) {
      problem(r, "tet " + std::to_string(t) + " has a vertex id out of range");
      continue;
    }
    if (!positive[t]) {
      ++r.nb_inverted;
      problem(r, "tet " + std::to_string(t) + " is inverted or flat");
    }
    for (int f = 0; f < 4; ++f) {
      const int ci = constraint_of(tv, f);
      const int o = m.adj[4 * t + f];
      if (o < 0) {
        if (ci < 0) {
          ++r.nb_open_faces;
          problem(r, "boundary face of tet " + std::to_string(t) +
                         " is not a boundary triangle (boundary not closed)");
        }
        continue;
      }
      const int t2 = o / 4, f2 = o % 4;
      if (o >= 4 * nt || m.tets[4 * t2] < 0 || m.adj[o] != 4 * t + f) {
        ++r.nb_bad_adjacency;
        problem(r, "adjacency of tet " + std::to_string(t) + " face " + std::to_string(f) +
                       " is not symmetric or points to a dead tet");
        continue;
      }
      if (!same_face(tv, f, t2, f2)) {
        ++r.nb_bad_adjacency;
        problem(r, "tets " + std::to_string(t) + " and " + std::to_string(t2) +
                       " are adjacent but do not share the face");
      } else if (positive[t] && positive[t2] && !opposite_sides(tv, f, t2, f2)) {
        ++r.nb_bad_adjacency;
        problem(r, "tets " + std::to_string(t) + " and " + std::to_string(t2) +
                       " overlap: they stand on the same side of their common face");
      }
      if (m.tet_region[t] != m.tet_region[t2] && ci < 0) {
        ++r.nb_open_faces;
        problem(r, "interface between regions " + std::to_string(m.tet_region[t]) + " and " +
                       std::to_string(m.tet_region[t2]) + " is not a constrained triangle");
      }
    }
  }
  for (const auto& [k, i] : constrained)
    if (holders[i] > 2 || (holders[i] == 2 && open_holders[i] != 0)) {
      ++r.nb_bad_adjacency;
      problem(r, "boundary triangle (" + std::to_string(k[0]) + "," + std::to_string(k[1]) + "," +
                     std::to_string(k[2]) + ") is a face of " + std::to_string(holders[i]) +
                     " tets" + (holders[i] == 2 ? " that are not adjacent" : "") +
                     " (tets overlap there)");
    }
  for (const auto& [k, i] : constrained)
    if (!holders[i]) {
      ++r.nb_dangling_constraints;
      problem(r, "boundary triangle (" + std::to_string(k[0]) + "," + std::to_string(k[1]) + "," +
                     std::to_string(k[2]) + ") is not a face of any tet");
    }
  return r;
}

MeshCheck check_mesh(const TriMesh2& m) {
  MeshCheck r;
  const int nv = m.nb_vertices(), nt = m.nb_tris();
  if (static_cast<int>(m.tri_region.size()) != nt) problem(r, "tri_region size differs from #T");
  if (static_cast<int>(m.vclass.size()) != nv) problem(r, "vclass size differs from #V");
  if (m.adj.size() != m.tris.size()) {
    problem(r, "adjacency not built (adj size differs from 3*#T)");
    return r;
  }
  std::unordered_set<EdgeKey, EdgeKeyHash> constrained, seen;
  // Per constrained edge: the live triangles on it and those of them with nothing behind it (1
  // and 1 on the boundary, 2 and 0 on an interface; else triangles overlap there).
  std::unordered_map<EdgeKey, std::array<int, 2>, EdgeKeyHash> held;
  for (int e = 0; e < m.nb_edges(); ++e) {
    const int a = m.edges[2 * e], b = m.edges[2 * e + 1];
    if (a < 0 || a >= nv || b < 0 || b >= nv) {
      problem(r, "edge " + std::to_string(e) + " has a vertex id out of range");
      return r;
    }
    constrained.insert(edge_key(a, b));
  }
  for (int t = 0; t < nt; ++t) {
    const int* tv = &m.tris[3 * t];
    if (tv[0] < 0) continue;
    bool in_range = true;
    for (int k = 0; k < 3; ++k)
      if (tv[k] < 0 || tv[k] >= nv) in_range = false;
    if (!in_range) {
      problem(r, "triangle " + std::to_string(t) + " has a vertex id out of range");
      continue;
    }
    const bool positive = orient2d(m.point(tv[0]), m.point(tv[1]), m.point(tv[2])) > 0;
    if (!positive) {
      ++r.nb_inverted;
      problem(r, "triangle " + std::to_string(t) + " is inverted or flat");
    }
    for (int e = 0; e < 3; ++e) {
      const EdgeKey key = edge_key(tv[(e + 1) % 3], tv[(e + 2) % 3]);
      seen.insert(key);
      const int o = m.adj[3 * t + e];
      if (constrained.count(key)) {
        auto& h = held[key];
        ++h[0];
        if (o < 0) ++h[1];
      }
      if (o < 0) {
        if (!constrained.count(key)) {
          ++r.nb_open_faces;
          problem(r, "boundary edge of triangle " + std::to_string(t) + " is not a boundary edge");
        }
        continue;
      }
      const int t2 = o / 3, e2 = o % 3;
      if (t2 >= nt || m.tris[3 * t2] < 0 || m.adj[o] != 3 * t + e) {
        ++r.nb_bad_adjacency;
        problem(r, "adjacency of triangle " + std::to_string(t) + " is not symmetric");
        continue;
      }
      const int* tv2 = &m.tris[3 * t2];
      if (edge_key(tv2[(e2 + 1) % 3], tv2[(e2 + 2) % 3]) != key) {
        ++r.nb_bad_adjacency;
        problem(r, "triangles " + std::to_string(t) + " and " + std::to_string(t2) +
                       " are adjacent but do not share the edge");
      } else if (positive && tv2[(e2 + 1) % 3] == tv[(e + 1) % 3] &&
                 orient2d(m.point(tv2[0]), m.point(tv2[1]), m.point(tv2[2])) > 0) {
        // Two positive triangles list their common edge in opposite directions when they lie on
        // its two sides.
        ++r.nb_bad_adjacency;
        problem(r, "triangles " + std::to_string(t) + " and " + std::to_string(t2) +
                       " overlap: they lie on the same side of their common edge");
      }
      if (m.tri_region[t] != m.tri_region[t2] && !constrained.count(key)) {
        ++r.nb_open_faces;
        problem(r, "interface between surfaces is not a constrained edge");
      }
    }
  }
  for (const auto& [k, h] : held)
    if (h[0] > 2 || (h[0] == 2 && h[1] != 0)) {
      ++r.nb_bad_adjacency;
      problem(r, "boundary edge (" + std::to_string(k[0]) + "," + std::to_string(k[1]) +
                     ") is an edge of " + std::to_string(h[0]) + " triangles" +
                     (h[0] == 2 ? " that are not adjacent" : "") + " (triangles overlap there)");
    }
  for (const EdgeKey& k : constrained)
    if (!seen.count(k)) {
      ++r.nb_dangling_constraints;
      problem(r, "boundary edge (" + std::to_string(k[0]) + "," + std::to_string(k[1]) +
                     ") is not an edge of any triangle");
    }
  return r;
}

}  // namespace cvtmesh
