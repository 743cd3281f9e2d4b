#include "core/boundary/surface_folds.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "core/geometry/vec3.h"

namespace cvtmesh {
namespace {

const int* tri(const TetMesh& m, int f) {
  return &m.tris[3 * static_cast<std::size_t>(f)];
}

// Whether triangle w holds the directed edge p -> q.
bool has_directed(const int* w, int p, int q) {
  for (int k = 0; k < 3; ++k)
    if (w[k] == p && w[(k + 1) % 3] == q) return true;
  return false;
}

// The unit normal of (x, y, z) ({0,0,0} if degenerate).
Vec3 unit_normal(const double* x, const double* y, const double* z) {
  const Vec3 n = cross(sub(y, x), sub(z, x));
  const double l = norm(n);
  return l > 0 ? (1 / l) * n : Vec3{0, 0, 0};
}

// cos of the turn across edge (p, q) between triangles u and w (vertex triples), each normal
// taken with u's turning sense (w's reversed if it holds p -> q in the same direction as u).
template <class At>
double turn(const int* u, const int* w, int p, int q, At at) {
  const Vec3 nu = unit_normal(at(u[0]), at(u[1]), at(u[2]));
  const Vec3 nw = unit_normal(at(w[0]), at(w[1]), at(w[2]));
  const bool same_way = has_directed(u, p, q) == has_directed(w, p, q);
  return same_way ? -dot(nu, nw) : dot(nu, nw);
}

// The only other boundary triangle at edge (p, q) than `not_this` (from p's fan), -1 if there is
// none or more than one (an open or non-manifold edge: no turn to keep).
int other_triangle(const TetMesh& m, const BoundaryFans& fans, int p, int q, int not_this,
                   int also_not = -1) {
  int found = -1;
  for (const int* f = fans.begin_of(p); f != fans.end_of(p); ++f) {
    if (*f == not_this || *f == also_not) continue;
    const int* w = tri(m, *f);
    if (w[0] != q && w[1] != q && w[2] != q) continue;
    if (found >= 0) return -1;
    found = *f;
  }
  return found;
}

}  // namespace

double cos_turn(const TetMesh& m, int f, int g, int p, int q) {
  return turn(tri(m, f), tri(m, g), p, q, [&](int x) { return m.point(x); });
}

std::array<int, 6> flipped_triangles(const TetMesh& m, int f1, int a, int b, int c, int d) {
  // f1 turning from b to a: its cycle is (b, a, c), the quad's a -> c -> b -> d -> a.
  return has_directed(tri(m, f1), b, a) ? std::array<int, 6>{a, c, d, b, d, c}
                                        : std::array<int, 6>{a, d, c, b, c, d};
}

void retarget_flipped_triangles(TetMesh& m, int f1, int f2, int a, int b, int c, int d) {
  const std::array<int, 6> t = flipped_triangles(m, f1, a, b, c, d);
  int* w1 = &m.tris[3 * static_cast<std::size_t>(f1)];
  int* w2 = &m.tris[3 * static_cast<std::size_t>(f2)];
  for (int k = 0; k < 3; ++k) {
    w1[k] = t[k];
    w2[k] = t[3 + k];
  }
}

bool move_folds_surface(const TetMesh& m, const BoundaryFans& fans, int v, const double* position,
                        double floor) {
  auto now = [&](int w) { return m.point(w); };
  auto moved = [&](int w) { return w == v ? position : m.point(w); };
  for (const int* f = fans.begin_of(v); f != fans.end_of(v); ++f) {
    const int* u = tri(m, *f);
    for (int k = 0; k < 3; ++k) {
      const int p = u[k], q = u[(k + 1) % 3];
      const int g = other_triangle(m, fans, p, q, *f);
      if (g < 0) continue;
      const int* w = tri(m, g);
      const double after = turn(u, w, p, q, moved);
      if (after >= floor) continue;
      if (after < turn(u, w, p, q, now)) return true;
    }
  }
  return false;
}

bool flip_folds_surface(const TetMesh& m, const BoundaryFans& fans, int f1, int f2, int a, int b,
                        int c, int d, double pair_floor, double floor) {
  auto at = [&](int w) { return m.point(w); };
  const std::array<int, 6> t = flipped_triangles(m, f1, a, b, c, d);
  const int* n1 = t.data();
  const int* n2 = t.data() + 3;
  if (turn(n1, n2, c, d, at) < pair_floor) return true;
  // Each outer edge: the old triangle that held it, the new one that does, the neighbour.
  const int outer[4][3] = {{a, c, 1}, {c, b, 1}, {b, d, 2}, {d, a, 2}};
  for (const auto& e : outer) {
    const int p = e[0], q = e[1];
    const int* old_t = tri(m, e[2] == 1 ? f1 : f2);
    const int* new_t = (p == a || q == a) ? n1 : n2;
    const int g = other_triangle(m, fans, p, q, f1, f2);
    if (g < 0) continue;
    const int* w = tri(m, g);
    const double after = turn(new_t, w, p, q, at);
    if (after >= floor) continue;
    if (after < turn(old_t, w, p, q, at)) return true;
  }
  return false;
}

}  // namespace cvtmesh
