#include "core/swap/local_mesh.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

#include "core/geometry/predicates.h"
#include "core/mesh/build_adjacency.h"
#include "core/swap/apply_swap.h"

namespace cvtmesh {
namespace {

using Quad = std::array<int, 4>;

Quad sorted_quad(const int* v) {
  Quad q{v[0], v[1], v[2], v[3]};
  std::sort(q.begin(), q.end());
  return q;
}

// The live tets of m as sorted vertex quadruples, sorted, with their tet ids.
std::vector<std::pair<Quad, int>> quads_of(const TetMesh& m) {
  std::vector<std::pair<Quad, int>> q;
  for (int t = 0; t < m.nb_tets(); ++t)
    if (m.tets[4 * static_cast<std::size_t>(t)] >= 0)
      q.push_back({sorted_quad(&m.tets[4 * static_cast<std::size_t>(t)]), t});
  std::sort(q.begin(), q.end());
  return q;
}

bool contains(const std::vector<std::pair<Quad, int>>& set, const Quad& q) {
  const auto it = std::lower_bound(set.begin(), set.end(), std::pair<Quad, int>{q, -1});
  return it != set.end() && it->first == q;
}

}  // namespace

LocalMesh extract_local_mesh(const TetMesh& mesh, const ConstrainedFaces& constrained,
                             const std::vector<int>& tets) {
  LocalMesh local;
  std::vector<int> ids = tets;
  std::sort(ids.begin(), ids.end());
  if (std::adjacent_find(ids.begin(), ids.end()) != ids.end())
    throw std::invalid_argument("extract_local_mesh: a tet is listed twice");
  auto in_set = [&](int t) { return std::binary_search(ids.begin(), ids.end(), t); };
  for (int t : tets) {
    if (t < 0 || t >= mesh.nb_tets() || mesh.tets[4 * static_cast<std::size_t>(t)] < 0)
      throw std::invalid_argument("extract_local_mesh: tet " + std::to_string(t) + " is not live");
    if (mesh.tet_region[t] != mesh.tet_region[tets.front()])
      throw std::invalid_argument("extract_local_mesh: the tets are not all of one region");
  }
  if (!tets.empty()) local.region = mesh.tet_region[tets.front()];
  std::vector<int>& gv = local.global_vertex;
  for (int t : tets) {
    const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
    gv.insert(gv.end(), tv, tv + 4);
  }
  std::sort(gv.begin(), gv.end());
  gv.erase(std::unique(gv.begin(), gv.end()), gv.end());
  auto local_of = [&](int v) {
    return static_cast<int>(std::lower_bound(gv.begin(), gv.end(), v) - gv.begin());
  };
  TetMesh& m = local.mesh;
  for (int v : gv) {
    m.xyz.insert(m.xyz.end(), mesh.point(v), mesh.point(v) + 3);
    m.vclass.push_back(mesh.vclass[v]);
  }
  local.global_tet = tets;
  for (int t : tets) {
    const int* tv = &mesh.tets[4 * static_cast<std::size_t>(t)];
    for (int k = 0; k < 4; ++k) m.tets.push_back(local_of(tv[k]));
    m.tet_region.push_back(local.region);
    for (int f = 0; f < 4; ++f) {
      const int behind = mesh.adj[4 * static_cast<std::size_t>(t) + f];
      const int a = tv[kTetFace[f][0]], b = tv[kTetFace[f][1]], c = tv[kTetFace[f][2]];
      const bool boundary = behind < 0 || !in_set(behind / 4);
      // A constrained face between two of the tets is listed once (from the lower tet id).
      if (boundary || (t < behind / 4 && constrained.count(face_key(a, b, c)))) {
        m.tris.insert(m.tris.end(), {local_of(a), local_of(b), local_of(c)});
        m.tri_surface.push_back(0);
      }
    }
  }
  // A vertex on the copy's boundary (or on a constrained face) is fixed in the copy; a free
  // vertex of the mesh inside it has its whole star in the copy (a face of the star on the copy's
  // boundary would hold it).
  for (int f = 0; f < m.nb_tris(); ++f)
    for (int k = 0; k < 3; ++k) {
      VertexClass& c = m.vclass[m.tris[3 * f + k]];
      if (c.dim == 3) c.dim = 2;
    }
  build_adjacency(m);
  return local;
}

bool commit_local_mesh(TetMesh& mesh, const LocalMesh& local, const TetMesh& after,
                       std::vector<int>* free_slots) {
  const TetMesh& before = local.mesh;
  const int n0 = before.nb_vertices(), n1 = after.nb_vertices();
  if (n1 < n0) return false;
  for (int i = 0; i < n0; ++i)
    if (before.vclass[i].dim < 3)
      for (int d = 0; d < 3; ++d)
        if (before.point(i)[d] != after.point(i)[d]) return false;
  for (int i = n0; i < n1; ++i)
    if (after.vclass[i].dim != 3) return false;
  for (int t = 0; t < after.nb_tets(); ++t) {
    const int* tv = &after.tets[4 * static_cast<std::size_t>(t)];
    if (tv[0] < 0) continue;
    if (orient3d(after.point(tv[0]), after.point(tv[1]), after.point(tv[2]), after.point(tv[3])) <=
        0)
      return false;
  }
  // The copy's constrained triangles (its hull, the constrained faces inside it) are faces of
  // `after`'s tets: an operation that lost one would cut the mesh or delete a surface triangle.
  {
    std::vector<std::array<int, 3>> faces;
    for (int t = 0; t < after.nb_tets(); ++t) {
      const int* tv = &after.tets[4 * static_cast<std::size_t>(t)];
      if (tv[0] < 0) continue;
      for (int f = 0; f < 4; ++f) {
        std::array<int, 3> k{tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]]};
        std::sort(k.begin(), k.end());
        faces.push_back(k);
      }
    }
    std::sort(faces.begin(), faces.end());
    for (int f = 0; f < before.nb_tris(); ++f) {
      std::array<int, 3> k{before.tris[3 * f], before.tris[3 * f + 1], before.tris[3 * f + 2]};
      if (k[0] < 0) continue;
      std::sort(k.begin(), k.end());
      if (!std::binary_search(faces.begin(), faces.end(), k)) return false;
    }
  }
  const auto qb = quads_of(before), qa = quads_of(after);
  SwapPlan plan;
  plan.region = local.region;
  for (const auto& [q, t] : qb)
    if (!contains(qa, q)) plan.old_tets.push_back(local.global_tet[t]);
  const int first_new = mesh.nb_vertices();
  auto global_of = [&](int v) { return v < n0 ? local.global_vertex[v] : first_new + (v - n0); };
  for (const auto& [q, t] : qa)
    if (!contains(qb, q)) {
      const int* tv = &after.tets[4 * static_cast<std::size_t>(t)];
      plan.new_tets.push_back(
          {global_of(tv[0]), global_of(tv[1]), global_of(tv[2]), global_of(tv[3])});
    }
  std::sort(plan.old_tets.begin(), plan.old_tets.end());
  // The move: coordinates, new vertices, then the tets.
  for (int i = 0; i < n0; ++i)
    if (before.vclass[i].dim == 3)
      std::copy(after.point(i), after.point(i) + 3, mesh.point(local.global_vertex[i]));
  const bool with_tags = mesh.node_tags.size() == static_cast<std::size_t>(first_new);
  for (int i = n0; i < n1; ++i) {
    mesh.xyz.insert(mesh.xyz.end(), after.point(i), after.point(i) + 3);
    mesh.vclass.push_back(VertexClass{3, local.region});
    if (with_tags) mesh.node_tags.push_back(0);
  }
  if (!plan.old_tets.empty() || !plan.new_tets.empty()) apply_swap(mesh, plan, free_slots);
  return true;
}

}  // namespace cvtmesh
