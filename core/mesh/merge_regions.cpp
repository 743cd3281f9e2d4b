#include "core/mesh/merge_regions.h"

#include <algorithm>
#include <string>

#include "core/mesh/build_adjacency.h"
#include "core/mesh/face_key.h"
#include "core/util/error.h"

namespace cvtmesh {

namespace {

// The parent vertex of each vertex of `sub` (appending the new ones to parent); moves the parent's
// vertices to their optimized positions.
std::vector<int> merge_vertices(TetMesh& parent, const RegionSubmesh& x, const TetMesh& sub,
                                bool allow_lost) {
  const int ns = static_cast<int>(x.to_parent.size());
  // Each vertex of the result: a parent vertex (its tag i + 1) or a new one (tag 0), appended.
  std::vector<int> to_parent(sub.nb_vertices(), -1);
  std::vector<char> seen(ns, 0);
  if (sub.node_tags.size() != static_cast<std::size_t>(sub.nb_vertices()))
    throw InvariantError("merge_regions: the optimized part lost its vertex tags");
  for (int v = 0; v < sub.nb_vertices(); ++v) {
    const std::size_t tag = sub.node_tags[v];
    if (tag == 0) continue;
    if (tag > static_cast<std::size_t>(ns) || seen[tag - 1])
      throw InvariantError("merge_regions: vertex tag " + std::to_string(tag) + " out of place");
    seen[tag - 1] = 1;
    to_parent[v] = x.to_parent[tag - 1];
  }
  // A free boundary's surface coarsening may remove a surface vertex (it stays in the parent,
  // in no element, for the caller to drop); an interface vertex never goes.
  for (int i = 0; i < ns; ++i)
    if (!seen[i] && (!allow_lost || x.mesh.vclass[i].entity < 0))
      throw InvariantError("merge_regions: the optimized part lost a vertex");
  // The parent's vertices take their new positions (their classification stays: the sub's
  // boundary was kept); the pinned ones (the interface) must not have moved.
  for (int v = 0; v < sub.nb_vertices(); ++v) {
    const int p = to_parent[v];
    if (p >= 0) {
      const bool pinned = x.mesh.vclass[sub.node_tags[v] - 1].entity < 0;
      if (pinned && !std::equal(sub.point(v), sub.point(v) + 3, parent.point(p)))
        throw InvariantError("merge_regions: an interface vertex moved");
      std::copy(sub.point(v), sub.point(v) + 3, parent.point(p));
      continue;
    }
    to_parent[v] = parent.nb_vertices();
    parent.xyz.insert(parent.xyz.end(), sub.point(v), sub.point(v) + 3);
    parent.vclass.push_back(sub.vclass[v]);
    if (!parent.node_tags.empty()) parent.node_tags.push_back(0);
  }
  return to_parent;
}

// Triangles: the parent's carried ones must come back (unless the boundary moved), and the added
// interface faces always.
void check_carried_triangles(const TetMesh& parent, const RegionSubmesh& x, const TetMesh& sub,
                             const std::vector<int>& to_parent, bool boundary_moved) {
  std::vector<FaceKey> carried, got, added, added_back;
  const int added_surface = x.nb_added_faces ? x.mesh.tri_surface.back() : 0;
  for (int f = 0; f < x.mesh.nb_tris(); ++f)
    if (x.nb_added_faces && x.mesh.tri_surface[f] == added_surface)
      added.push_back(face_key(x.to_parent[x.mesh.tris[3 * f]], x.to_parent[x.mesh.tris[3 * f + 1]],
                               x.to_parent[x.mesh.tris[3 * f + 2]]));
  for (int f = 0; f < sub.nb_tris(); ++f) {
    const bool is_added = x.nb_added_faces && sub.tri_surface[f] == added_surface;
    (is_added ? added_back : got)
        .push_back(face_key(to_parent[sub.tris[3 * f]], to_parent[sub.tris[3 * f + 1]],
                            to_parent[sub.tris[3 * f + 2]]));
  }
  std::sort(added.begin(), added.end());
  std::sort(added_back.begin(), added_back.end());
  if (added != added_back)
    throw InvariantError("merge_regions: the optimized part changed its interface");
  if (boundary_moved) return;
  for (int f = 0; f < parent.nb_tris(); ++f)
    if (x.selected_tri[f])
      carried.push_back(
          face_key(parent.tris[3 * f], parent.tris[3 * f + 1], parent.tris[3 * f + 2]));
  std::sort(carried.begin(), carried.end());
  std::sort(got.begin(), got.end());
  if (carried != got)
    throw InvariantError("merge_regions: the optimized part changed its boundary triangles");
}

// The parent's triangles no part carried or two parts did (an interface between volumes on the
// cut: its vertices were pinned in both), in order, then each part's own (not its interface's).
void replace_carried_triangles(TetMesh& parent, const std::vector<const RegionSubmesh*>& xs,
                               const std::vector<const TetMesh*>& subs,
                               const std::vector<std::vector<int>>& to_parent) {
  std::vector<int> carried(parent.nb_tris(), 0);
  for (const RegionSubmesh* x : xs)
    for (int f = 0; f < parent.nb_tris(); ++f) carried[f] += x->selected_tri[f];
  std::vector<FaceKey> shared;
  for (int f = 0; f < parent.nb_tris(); ++f)
    if (carried[f] > 1)
      shared.push_back(
          face_key(parent.tris[3 * f], parent.tris[3 * f + 1], parent.tris[3 * f + 2]));
  std::sort(shared.begin(), shared.end());
  const bool with_tags = !parent.tri_tags.empty();
  std::vector<int> tris, surface;
  std::vector<std::size_t> tags;
  for (int f = 0; f < parent.nb_tris(); ++f) {
    if (carried[f] == 1) continue;
    tris.insert(tris.end(), &parent.tris[3 * f], &parent.tris[3 * f] + 3);
    surface.push_back(parent.tri_surface[f]);
    if (with_tags) tags.push_back(parent.tri_tags[f]);
  }
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const RegionSubmesh& x = *xs[i];
    const TetMesh& sub = *subs[i];
    const int added_surface = x.nb_added_faces ? x.mesh.tri_surface.back() : 0;
    for (int f = 0; f < sub.nb_tris(); ++f) {
      if (x.nb_added_faces && sub.tri_surface[f] == added_surface) continue;
      const int* v = &sub.tris[3 * f];
      if (!shared.empty() &&
          std::binary_search(shared.begin(), shared.end(),
                             face_key(to_parent[i][v[0]], to_parent[i][v[1]], to_parent[i][v[2]])))
        continue;
      for (int k = 0; k < 3; ++k) tris.push_back(to_parent[i][v[k]]);
      surface.push_back(sub.tri_surface[f]);
      if (with_tags)
        tags.push_back(f < static_cast<int>(sub.tri_tags.size()) ? sub.tri_tags[f] : 0);
    }
  }
  parent.tris = std::move(tris);
  parent.tri_surface = std::move(surface);
  if (with_tags) parent.tri_tags = std::move(tags);
}

}  // namespace

void merge_regions(TetMesh& parent, const RegionSubmesh& x, const TetMesh& sub) {
  merge_parts(parent, {&x}, {&sub});
}

void merge_parts(TetMesh& parent, const std::vector<const RegionSubmesh*>& xs,
                 const std::vector<const TetMesh*>& subs, bool boundary_moved) {
  if (xs.size() != subs.size())
    throw InvariantError("merge_parts: as many optimized parts as extracted ones");
  const int nt = parent.nb_tets();
  std::vector<char> selected(nt, 0);
  for (const RegionSubmesh* x : xs)
    for (int t = 0; t < nt; ++t) {
      if (!x->selected_tet[t]) continue;
      if (selected[t]) throw InvariantError("merge_parts: the parts overlap");
      selected[t] = 1;
    }
  std::vector<std::vector<int>> to_parent(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) {
    to_parent[i] = merge_vertices(parent, *xs[i], *subs[i], boundary_moved);
    check_carried_triangles(parent, *xs[i], *subs[i], to_parent[i], boundary_moved);
  }
  // Tets: the unselected ones in their order, then each sub's.
  std::vector<int> tets, region;
  std::vector<std::size_t> tags;
  const bool with_tags = !parent.tet_tags.empty();
  for (int t = 0; t < nt; ++t) {
    if (selected[t] || parent.tets[4 * t] < 0) continue;
    tets.insert(tets.end(), &parent.tets[4 * t], &parent.tets[4 * t] + 4);
    region.push_back(parent.tet_region[t]);
    if (with_tags) tags.push_back(parent.tet_tags[t]);
  }
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const TetMesh& sub = *subs[i];
    for (int t = 0; t < sub.nb_tets(); ++t) {
      if (sub.tets[4 * t] < 0) continue;
      for (int k = 0; k < 4; ++k) tets.push_back(to_parent[i][sub.tets[4 * t + k]]);
      region.push_back(sub.tet_region[t]);
      if (with_tags)
        tags.push_back(t < static_cast<int>(sub.tet_tags.size()) ? sub.tet_tags[t] : 0);
    }
  }
  parent.tets = std::move(tets);
  parent.tet_region = std::move(region);
  if (with_tags) parent.tet_tags = std::move(tags);
  if (boundary_moved) replace_carried_triangles(parent, xs, subs, to_parent);
  build_adjacency(parent);
}

}  // namespace cvtmesh
