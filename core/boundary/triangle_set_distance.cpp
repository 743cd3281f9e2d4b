#include "core/boundary/triangle_set_distance.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <limits>

namespace cvtmesh {
namespace {

using K = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<K::Triangle_3>;
using Segments = std::vector<K::Segment_3>;
using TriPrimitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using TriTree = CGAL::AABB_tree<CGAL::AABB_traits<K, TriPrimitive>>;
using SegPrimitive = CGAL::AABB_segment_primitive<K, Segments::const_iterator>;
using SegTree = CGAL::AABB_tree<CGAL::AABB_traits<K, SegPrimitive>>;

K::Point_3 point(const std::vector<double>& xyz, int i) {
  const std::size_t k = 3 * static_cast<std::size_t>(i);
  return {xyz[k], xyz[k + 1], xyz[k + 2]};
}

}  // namespace

struct TriangleSetDistance::Impl {
  // Distinct for every set built in the process (a thread's last answer names its set by it: an
  // address may be reused by a later set).
  std::uint64_t serial = next_serial.fetch_add(1, std::memory_order_relaxed);
  static inline std::atomic<std::uint64_t> next_serial{1};
  Triangles triangles;
  std::vector<int> index;  // of each triangle in the constructor's tris
  TriTree tree;
};

TriangleSetDistance::TriangleSetDistance(const std::vector<double>& xyz,
                                         const std::vector<int>& tris)
    : impl_(std::make_unique<Impl>()) {
  for (std::size_t f = 0; f + 2 < tris.size(); f += 3) {
    K::Triangle_3 t(point(xyz, tris[f]), point(xyz, tris[f + 1]), point(xyz, tris[f + 2]));
    if (!t.is_degenerate()) {
      impl_->triangles.push_back(t);
      impl_->index.push_back(static_cast<int>(f / 3));
    }
  }
  if (!impl_->triangles.empty()) {
    impl_->tree.insert(impl_->triangles.begin(), impl_->triangles.end());
    impl_->tree.build();
    impl_->tree.accelerate_distance_queries();
  }
}

TriangleSetDistance::~TriangleSetDistance() = default;

bool TriangleSetDistance::empty() const {
  return impl_->triangles.empty();
}

bool TriangleSetDistance::closest(const double* p, double* q) const {
  if (impl_->triangles.empty()) return false;
  const K::Point_3 c = impl_->tree.closest_point(K::Point_3(p[0], p[1], p[2]));
  q[0] = c.x();
  q[1] = c.y();
  q[2] = c.z();
  return true;
}

int TriangleSetDistance::closest_triangle(const double* p, double* q) const {
  if (impl_->triangles.empty()) return -1;
  const auto [c, id] = impl_->tree.closest_point_and_primitive(K::Point_3(p[0], p[1], p[2]));
  q[0] = c.x();
  q[1] = c.y();
  q[2] = c.z();
  return impl_->index[static_cast<std::size_t>(id - impl_->triangles.cbegin())];
}

double TriangleSetDistance::distance(const double* p) const {
  double q[3];
  if (!closest(p, q)) return std::numeric_limits<double>::infinity();
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                   (p[2] - q[2]) * (p[2] - q[2]));
}

namespace {

// An AABB tree traversal that stops at the first triangle whose closest point to p (the same
// construction as the tree's closest_point) is within r; it visits only the boxes within r.
// Whether triangle t's closest point to p (the same construction as the tree's closest_point)
// is within r.
bool triangle_within(const K::Triangle_3& t, const K::Point_3& p, double r) {
  const K::Point_3 q = K::Construct_projected_point_3()(t, p);
  const double d = std::sqrt((p.x() - q.x()) * (p.x() - q.x()) + (p.y() - q.y()) * (p.y() - q.y()) +
                             (p.z() - q.z()) * (p.z() - q.z()));
  return d <= r;
}

struct WithinTraversal {
  K::Point_3 p;
  double r;
  const K::Triangle_3* found = nullptr;

  bool go_further() const { return !found; }
  void intersection(const K::Point_3&, const TriPrimitive& primitive) {
    if (found) return;
    if (triangle_within(primitive.datum(), p, r)) found = &*primitive.id();
  }
  template <class Node>
  bool do_intersect(const K::Point_3&, const Node& node) const {
    const CGAL::Bbox_3& b = node.bbox();
    double d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double x = p[k], lo = b.min(k), hi = b.max(k);
      const double e = x < lo ? lo - x : x > hi ? x - hi : 0;
      d2 += e * e;
    }
    // A box is skipped only when it is clearly farther than r (rounding never loses a triangle).
    return std::sqrt(d2) <= r * (1 + 1e-9);
  }
};

}  // namespace

bool TriangleSetDistance::any_within(const double* p, double r) const {
  if (impl_->triangles.empty() || !(r >= 0)) return false;
  if (std::isinf(r)) return true;
  const K::Point_3 q(p[0], p[1], p[2]);
  // The triangles that answered this thread's last queries on this set first: the checks ask
  // about the samples of a vertex's fan one after the other, nearly always within r of one of a
  // few input triangles (the femur's boundary moves: fan_within_tolerance was 7 % of a run, most
  // of it in the traversal). The answer is the same (the same test on triangles the traversal
  // may reach: it reaches every triangle within r); only which thread asked before changes the
  // work.
  constexpr int kRecent = 8;
  thread_local std::uint64_t recent_set = 0;
  thread_local std::array<std::size_t, kRecent> recent{};
  thread_local int nb_recent = 0, next = 0;
  const Triangles& all = impl_->triangles;
  if (recent_set != impl_->serial) {
    recent_set = impl_->serial;
    nb_recent = next = 0;
  }
  for (int i = 0; i < nb_recent; ++i) {
    const K::Triangle_3& t = all[recent[i]];
    // Its bounding box first (cheaper than the projection; most of the recent ones are far).
    bool near = true;
    for (int k = 0; k < 3 && near; ++k) {
      const double lo = std::min({t[0][k], t[1][k], t[2][k]}),
                   hi = std::max({t[0][k], t[1][k], t[2][k]});
      near = q[k] >= lo - r && q[k] <= hi + r;
    }
    if (near && triangle_within(t, q, r)) return true;
  }
  WithinTraversal w{q, r};
  impl_->tree.traversal(w.p, w);
  if (!w.found) return false;
  recent[next] = static_cast<std::size_t>(w.found - all.data());
  next = (next + 1) % kRecent;
  nb_recent = std::min(nb_recent + 1, kRecent);
  return true;
}

struct SegmentSetDistance::Impl {
  Segments segments;
  SegTree tree;
};

SegmentSetDistance::SegmentSetDistance(const std::vector<double>& xyz,
                                       const std::vector<int>& segments)
    : impl_(std::make_unique<Impl>()) {
  for (std::size_t e = 0; e + 1 < segments.size(); e += 2) {
    K::Segment_3 s(point(xyz, segments[e]), point(xyz, segments[e + 1]));
    if (!s.is_degenerate()) impl_->segments.push_back(s);
  }
  if (!impl_->segments.empty()) {
    impl_->tree.insert(impl_->segments.begin(), impl_->segments.end());
    impl_->tree.build();
    impl_->tree.accelerate_distance_queries();
  }
}

SegmentSetDistance::~SegmentSetDistance() = default;

bool SegmentSetDistance::empty() const {
  return impl_->segments.empty();
}

bool SegmentSetDistance::closest(const double* p, double* q) const {
  if (impl_->segments.empty()) return false;
  const K::Point_3 c = impl_->tree.closest_point(K::Point_3(p[0], p[1], p[2]));
  q[0] = c.x();
  q[1] = c.y();
  q[2] = c.z();
  return true;
}

double point_triangle_distance(const double* p, const double* a, const double* b, const double* c) {
  const K::Triangle_3 t(K::Point_3(a[0], a[1], a[2]), K::Point_3(b[0], b[1], b[2]),
                        K::Point_3(c[0], c[1], c[2]));
  const K::Point_3 q(p[0], p[1], p[2]);
  if (t.is_degenerate()) {
    double best = std::numeric_limits<double>::infinity();
    for (const double* x : {a, b, c})
      best =
          std::min(best, std::sqrt((p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]) +
                                   (p[2] - x[2]) * (p[2] - x[2])));
    return best;
  }
  return std::sqrt(CGAL::to_double(CGAL::squared_distance(q, t)));
}

}  // namespace cvtmesh
