// Closest points on a set of triangles in 3D (a CGAL AABB tree; no hand-written search tree).
#pragma once
#include <memory>
#include <vector>

namespace cvtmesh {

class TriangleSetDistance {
 public:
  // xyz: #P by 3 coordinates; tris: #F by 3 point ids (0-based, any orientation). Degenerate
  // (zero-area) triangles are skipped. Copies what it needs.
  TriangleSetDistance(const std::vector<double>& xyz, const std::vector<int>& tris);
  ~TriangleSetDistance();
  TriangleSetDistance(const TriangleSetDistance&) = delete;
  TriangleSetDistance& operator=(const TriangleSetDistance&) = delete;

  bool empty() const;
  // The closest point q (3) to p on the triangles; false if there are none. Thread-safe.
  bool closest(const double* p, double* q) const;
  double distance(const double* p) const;
  // Whether some triangle is within distance r of p: distance(p) <= r (up to the rounding of which
  // triangle is the closest), stopping at the first such triangle. Thread-safe.
  bool any_within(const double* p, double r) const;
  // The closest point q to p and the index (in the constructor's `tris`, #F) of a triangle it
  // lies on; -1 if there are none. Thread-safe.
  int closest_triangle(const double* p, double* q) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The same for polylines: segments (#E by 2 point ids).
class SegmentSetDistance {
 public:
  SegmentSetDistance(const std::vector<double>& xyz, const std::vector<int>& segments);
  ~SegmentSetDistance();
  SegmentSetDistance(const SegmentSetDistance&) = delete;
  SegmentSetDistance& operator=(const SegmentSetDistance&) = delete;

  bool empty() const;
  bool closest(const double* p, double* q) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Distance from p to triangle (a, b, c) (each 3 doubles).
double point_triangle_distance(const double* p, const double* a, const double* b, const double* c);

}  // namespace cvtmesh
