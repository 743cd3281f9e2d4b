#include "core/swap/flip2d.h"

#include "core/geometry/predicates.h"

namespace cvtmesh {

bool flip2d_possible(const TriMesh2& mesh, int slot) {
  const int o = mesh.adj[slot];
  if (o < 0) return false;
  const int t = slot / 3, e = slot % 3, t2 = o / 3, e2 = o % 3;
  const int* tv = &mesh.tris[3 * t];
  const int c = tv[e], a = tv[(e + 1) % 3], b = tv[(e + 2) % 3];
  const int d = mesh.tris[3 * t2 + e2];
  return orient2d(mesh.point(c), mesh.point(a), mesh.point(d)) > 0 &&
         orient2d(mesh.point(d), mesh.point(b), mesh.point(c)) > 0;
}

bool flip2d(TriMesh2& mesh, int slot) {
  if (!flip2d_possible(mesh, slot)) return false;
  const int o = mesh.adj[slot];
  const int t = slot / 3, e = slot % 3, t2 = o / 3, e2 = o % 3;
  int* tv = &mesh.tris[3 * t];
  int* tv2 = &mesh.tris[3 * t2];
  const int c = tv[e], a = tv[(e + 1) % 3], b = tv[(e + 2) % 3];
  const int d = tv2[e2];
  // Outer neighbours, named by the edge they share.
  const int n_ad = mesh.adj[3 * t2 + (e2 + 1) % 3];  // t2's edge opposite b
  const int n_db = mesh.adj[3 * t2 + (e2 + 2) % 3];  // t2's edge opposite a
  const int n_ca = mesh.adj[3 * t + (e + 2) % 3];    // t's edge opposite b
  const int n_bc = mesh.adj[3 * t + (e + 1) % 3];    // t's edge opposite a
  tv[0] = c, tv[1] = a, tv[2] = d;
  tv2[0] = d, tv2[1] = b, tv2[2] = c;
  int* at = &mesh.adj[3 * t];
  int* at2 = &mesh.adj[3 * t2];
  at[0] = n_ad, at[1] = 3 * t2 + 1, at[2] = n_ca;
  at2[0] = n_bc, at2[1] = 3 * t + 1, at2[2] = n_db;
  if (n_ad >= 0) mesh.adj[n_ad] = 3 * t;
  if (n_ca >= 0) mesh.adj[n_ca] = 3 * t + 2;
  if (n_bc >= 0) mesh.adj[n_bc] = 3 * t2;
  if (n_db >= 0) mesh.adj[n_db] = 3 * t2 + 2;
  return true;
}

}  // namespace cvtmesh
