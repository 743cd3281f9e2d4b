// The geometry that measures on the input triangulation and projects by another
// (measure_on_input_boundary.h): its distance is an upper bound of the distance to the wrapped
// geometry, and the wrapped geometry is asked only where the cheap bound exceeds exact_above.
#include "core/pipeline/measure_on_input_boundary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace cvtmesh {
namespace {

// The unit sphere as one surface (id 7), counting its queries.
class UnitSphere final : public BoundaryGeometry {
 public:
  mutable long queries = 0;
  bool closest_on_surface(int s, const double* p, double* q) const override {
    ++queries;
    if (s != 7) return false;
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    if (!(r > 0)) return false;
    for (int d = 0; d < 3; ++d) q[d] = p[d] / r;
    return true;
  }
  bool closest_on_curve(int, const double*, double*) const override { return false; }
  double distance_to_boundary(const double* p) const override {
    ++queries;
    return std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1);
  }
  std::vector<double> samples() const override { return {}; }
  const char* kind() const override { return "cad"; }
};

// The octahedron inscribed in the unit sphere: its deviation from the sphere is 1 - 1/sqrt(3)
// (at the face centroids).
TetMesh octahedron() {
  TetMesh m;
  m.xyz = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  m.tris = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  m.tri_surface.assign(8, 7);
  return m;
}

TEST(MeasureOnInputBoundary, UpperBoundOfTheTrueDistanceAndCadQueriesOnlyAboveTheThreshold) {
  const TetMesh input = octahedron();
  auto sphere = std::make_shared<UnitSphere>();
  BoundaryModel b;
  b.geometry = sphere;
  b.reference_deviation = 1 - 1 / std::sqrt(3.0);
  const double exact_above = 0.5;
  const BoundaryModel m = measure_on_input_boundary(b, input, exact_above);
  EXPECT_STREQ(m.geometry->kind(), "cad");
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.3, 1.3);
  int cheap = 0, exact = 0;
  for (int i = 0; i < 2000; ++i) {
    const double p[3] = {u(rng), u(rng), u(rng)};
    const double truth = std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - 1);
    const long before = sphere->queries;
    const double d = m.geometry->distance_to_boundary(p);
    EXPECT_GE(d, truth - 1e-12) << "not an upper bound";
    if (sphere->queries == before) {
      ++cheap;
      EXPECT_LE(d, exact_above);  // answered without the CAD only below the threshold
    } else {
      ++exact;
      EXPECT_EQ(sphere->queries, before + 1);  // one projection, on the nearest surface
      EXPECT_LE(d, truth + 1e-12);             // the nearest surface is the sphere itself: exact
    }
  }
  EXPECT_GT(cheap, 0);
  EXPECT_GT(exact, 0);
  // Projections are the wrapped geometry's.
  const double p[3] = {0.3, 0.4, 1.2};
  double q[3];
  ASSERT_TRUE(m.geometry->closest_on_surface(7, p, q));
  EXPECT_NEAR(std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]), 1, 1e-15);
}

TEST(MeasureOnInputBoundary, WithoutGeometryTheModelIsReturnedAsItIs) {
  BoundaryModel b;
  b.diagonal = 2;
  const BoundaryModel m = measure_on_input_boundary(b, octahedron(), 0.1);
  EXPECT_FALSE(m.geometry);
  EXPECT_EQ(m.diagonal, 2);
}

}  // namespace
}  // namespace cvtmesh
