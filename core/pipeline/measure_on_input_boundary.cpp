#include "core/pipeline/measure_on_input_boundary.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "core/boundary/triangle_set_distance.h"

namespace cvtmesh {
namespace {

double distance(const double* a, const double* b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

class MeasuredOnInput final : public BoundaryGeometry {
 public:
  MeasuredOnInput(std::shared_ptr<const BoundaryGeometry> projector, const TetMesh& input,
                  double deviation, double exact_above)
      : projector_(std::move(projector)),
        input_(input.xyz, input.tris),
        tri_surface_(input.tri_surface),
        deviation_(deviation),
        exact_above_(exact_above) {}

  bool closest_on_surface(int s, const double* p, double* q) const override {
    return projector_->closest_on_surface(s, p, q);
  }
  bool closest_on_curve(int c, const double* p, double* q) const override {
    return projector_->closest_on_curve(c, p, q);
  }
  double distance_to_boundary(const double* p) const override {
    double q[3];
    const int f = input_.closest_triangle(p, q);
    if (f < 0) return projector_->distance_to_boundary(p);
    const double u = distance(p, q) + deviation_;
    if (u <= exact_above_) return u;
    double c[3];
    if (!projector_->closest_on_surface(tri_surface_[f], p, c)) return u;
    return std::min(u, distance(p, c));
  }
  std::vector<double> samples() const override { return projector_->samples(); }
  const char* kind() const override { return projector_->kind(); }
  bool thread_safe() const override { return projector_->thread_safe(); }

 private:
  std::shared_ptr<const BoundaryGeometry> projector_;
  TriangleSetDistance input_;
  std::vector<int> tri_surface_;
  double deviation_, exact_above_;
};

}  // namespace

BoundaryModel measure_on_input_boundary(BoundaryModel model, const TetMesh& input,
                                        double exact_above) {
  if (!model.geometry) return model;
  model.geometry = std::make_shared<MeasuredOnInput>(model.geometry, input,
                                                     model.reference_deviation, exact_above);
  return model;
}

}  // namespace cvtmesh
