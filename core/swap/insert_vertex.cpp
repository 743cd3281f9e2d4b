#include "core/swap/insert_vertex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/geometry/min_norm_in_hull.h"
#include "core/geometry/predicates.h"
#include "core/geometry/vec3.h"
#include "core/swap/apply_swap.h"

namespace cvtmesh {
namespace {

bool in(const std::vector<int>& v, int x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

const int* tet_of(const TetMesh& mesh, int t) {
  return &mesh.tets[4 * static_cast<std::size_t>(t)];
}

// True if tet n shares a constrained face with a tet of the cavity: adding it would put that face
// inside the cavity, and the insertion would delete it (an embedded surface's triangle, reached
// around the surface's free edge: t15's embedded surface lost one this way).
bool meets_cavity_across_constrained(const TetMesh& mesh, const ConstrainedFaces& constrained,
                                     const std::vector<int>& cavity, int n) {
  const int* nv = tet_of(mesh, n);
  for (int f = 0; f < 4; ++f) {
    const int behind = mesh.adj[4 * static_cast<std::size_t>(n) + f];
    if (behind < 0 || !in(cavity, behind / 4)) continue;
    if (constrained.count(face_key(nv[kTetFace[f][0]], nv[kTetFace[f][1]], nv[kTetFace[f][2]])))
      return true;
  }
  return false;
}

}  // namespace

std::vector<int> tet_cavity(const TetMesh& mesh, const ConstrainedFaces& constrained, int t) {
  std::vector<int> cavity = {t};
  const int* tv = tet_of(mesh, t);
  for (int f = 0; f < 4; ++f) {
    const int behind = mesh.adj[4 * static_cast<std::size_t>(t) + f];
    if (behind < 0 || mesh.tet_region[behind / 4] != mesh.tet_region[t]) continue;
    if (constrained.count(face_key(tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]])))
      continue;
    if (meets_cavity_across_constrained(mesh, constrained, cavity, behind / 4)) continue;
    cavity.push_back(behind / 4);
  }
  return cavity;
}

void grow_cavity(const TetMesh& mesh, const ConstrainedFaces& constrained, const double* p,
                 std::vector<int>& cavity, int max_size) {
  for (std::size_t i = 0; i < cavity.size(); ++i) {
    const int t = cavity[i];
    const int* tv = tet_of(mesh, t);
    for (int f = 0; f < 4; ++f) {
      if (static_cast<int>(cavity.size()) >= max_size) return;
      const int behind = mesh.adj[4 * static_cast<std::size_t>(t) + f];
      if (behind < 0) continue;
      const int n = behind / 4;
      if (mesh.tet_region[n] != mesh.tet_region[t] || in(cavity, n)) continue;
      if (constrained.count(face_key(tv[kTetFace[f][0]], tv[kTetFace[f][1]], tv[kTetFace[f][2]])))
        continue;
      const int* nv = tet_of(mesh, n);
      if (insphere(mesh.point(nv[0]), mesh.point(nv[1]), mesh.point(nv[2]), mesh.point(nv[3]), p) >
              0 &&
          !meets_cavity_across_constrained(mesh, constrained, cavity, n))
        cavity.push_back(n);
    }
  }
}

double cavity_kernel_center(const TetMesh& mesh, const std::vector<int>& cavity, double* p) {
  // The boundary faces' planes as inward unit normals m and offsets e: distance m.x - e.
  std::vector<Vec3> m;
  std::vector<double> e;
  Vec3 x{0, 0, 0};
  double nb = 0;
  for (int t : cavity) {
    const int* tv = tet_of(mesh, t);
    for (int f = 0; f < 4; ++f) {
      const int behind = mesh.adj[4 * static_cast<std::size_t>(t) + f];
      if (behind >= 0 && in(cavity, behind / 4)) continue;
      const double* a = mesh.point(tv[kTetFace[f][0]]);
      const Vec3 n = cross(sub(mesh.point(tv[kTetFace[f][1]]), a),
                           sub(mesh.point(tv[kTetFace[f][2]]), a));  // outwards
      const double len = norm(n);
      if (!(len > 0)) continue;
      m.push_back((-1 / len) * n);
      e.push_back(dot(m.back(), vec3(a)));
      for (int k = 0; k < 3; ++k) x = x + vec3(mesh.point(tv[kTetFace[f][k]]));
      nb += 3;
    }
  }
  if (m.empty()) {
    std::copy(x.begin(), x.end(), p);
    return -std::numeric_limits<double>::infinity();
  }
  x = (1 / nb) * x;
  double size = 0;  // of the cavity, for the tolerance of "active"
  for (std::size_t i = 0; i < m.size(); ++i) size = std::max(size, std::fabs(dot(m[i], x) - e[i]));
  const double band = 1e-9 * size;
  std::vector<double> val(m.size());
  std::vector<Vec3> active;
  auto evaluate = [&] {
    double fmin = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m.size(); ++i) {
      val[i] = dot(m[i], x) - e[i];
      fmin = std::min(fmin, val[i]);
    }
    return fmin;
  };
  double fmin = evaluate();
  for (int it = 0; it < 100; ++it) {
    active.clear();
    for (std::size_t i = 0; i < m.size(); ++i)
      if (val[i] <= fmin + band) active.push_back(m[i]);
    if (active.size() > 12) break;  // degenerate: stop where we are
    const Vec3 d = min_norm_in_hull(active);
    const double slope = norm2(d);
    if (!(slope > 1e-24)) break;  // the origin is in the hull: a maximum
    // Exact step: where the rising minimum meets the next plane's distance.
    double alpha = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < m.size(); ++i) {
      const double s = dot(m[i], d);
      if (val[i] > fmin + band && s < slope) alpha = std::min(alpha, (val[i] - fmin) / (slope - s));
    }
    if (!(alpha < std::numeric_limits<double>::infinity()) || !(alpha > 0)) break;
    const Vec3 prev = x;
    x = x + alpha * d;
    const double next = evaluate();
    if (!(next > fmin)) {  // rounding: keep the better point
      x = prev;
      fmin = evaluate();
      break;
    }
    fmin = next;
  }
  std::copy(x.begin(), x.end(), p);
  return fmin;
}

SwapPlan plan_insert_vertex(const TetMesh& mesh, const std::vector<int>& cavity, const double* p) {
  SwapPlan plan;
  plan.old_tets = cavity;
  if (cavity.empty()) {
    plan.status = SwapStatus::kNotConvex;
    return plan;
  }
  plan.region = mesh.tet_region[cavity.front()];
  const int nv = mesh.nb_vertices();
  std::vector<int> on_boundary;  // vertices of the cavity's boundary faces
  for (int t : cavity) {
    if (t < 0 || t >= mesh.nb_tets() || tet_of(mesh, t)[0] < 0)
      throw std::invalid_argument("plan_insert_vertex: tet " + std::to_string(t) +
                                  " is not a live tet");
    if (mesh.tet_region[t] != plan.region) {
      plan.status = SwapStatus::kMixedRegions;
      return plan;
    }
    const int* tv = tet_of(mesh, t);
    for (int f = 0; f < 4; ++f) {
      const int behind = mesh.adj[4 * static_cast<std::size_t>(t) + f];
      if (behind >= 0 && in(cavity, behind / 4)) continue;
      // The tet t with its vertex f replaced by p: positive iff p is on the side of the face
      // where t is.
      std::array<int, 4> nt = {tv[0], tv[1], tv[2], tv[3]};
      nt[f] = nv;
      const double* x[4];
      for (int k = 0; k < 4; ++k) x[k] = k == f ? p : mesh.point(tv[k]);
      if (orient3d(x[0], x[1], x[2], x[3]) <= 0) {
        plan.status = SwapStatus::kNotConvex;
        plan.new_tets.clear();
        return plan;
      }
      plan.new_tets.push_back(nt);
      for (int k = 0; k < 3; ++k) on_boundary.push_back(tv[kTetFace[f][k]]);
    }
  }
  std::sort(on_boundary.begin(), on_boundary.end());
  for (int t : cavity)
    for (int k = 0; k < 4; ++k)
      if (!std::binary_search(on_boundary.begin(), on_boundary.end(), tet_of(mesh, t)[k])) {
        plan.status = SwapStatus::kInteriorVertex;
        plan.new_tets.clear();
        return plan;
      }
  return plan;
}

int insert_vertex(TetMesh& mesh, SwapPlan& plan, const double* p, std::vector<int>* free_slots) {
  if (plan.status != SwapStatus::kOk)
    throw std::invalid_argument(std::string("insert_vertex: the plan is not valid (") +
                                swap_status_name(plan.status) + ")");
  const int v = mesh.nb_vertices();
  const bool with_tags = mesh.node_tags.size() == static_cast<std::size_t>(v);
  mesh.xyz.insert(mesh.xyz.end(), p, p + 3);
  mesh.vclass.push_back(VertexClass{3, plan.region});
  if (with_tags) mesh.node_tags.push_back(0);
  apply_swap(mesh, plan, free_slots);
  return v;
}

}  // namespace cvtmesh
