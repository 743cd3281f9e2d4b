// The free boundary on a CAD model reaches Gmsh only to project a vertex on its entity: the
// Hausdorff checks measure on the input triangulation (measure_on_input_boundary.h). A geometry
// that answered distance_to_boundary through the CAD (getClosestPoint on every surface, for every
// sample of every move) made `cvtmesh optimize t2.geo` 60x slower than the same model through a
// .msh; this test counts the queries instead of timing them. (On a coarse mesh of a curved CAD
// surface a sample near it may still ask the nearest surface: measure_on_input_boundary_test.)
#include <gmsh.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>

#include "core/io/gmsh_cad_boundary.h"
#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/pipeline/optimize.h"

namespace cvtmesh {
namespace {

struct Counts {
  std::atomic<long> projections{0}, distances{0};
};

// Forwards every query to the CAD geometry and counts them.
class CountingGeometry final : public BoundaryGeometry {
 public:
  CountingGeometry(std::shared_ptr<const BoundaryGeometry> g, std::shared_ptr<Counts> c)
      : g_(std::move(g)), c_(std::move(c)) {}
  bool closest_on_surface(int s, const double* p, double* q) const override {
    ++c_->projections;
    return g_->closest_on_surface(s, p, q);
  }
  bool closest_on_curve(int k, const double* p, double* q) const override {
    ++c_->projections;
    return g_->closest_on_curve(k, p, q);
  }
  double distance_to_boundary(const double* p) const override {
    ++c_->distances;
    return g_->distance_to_boundary(p);
  }
  std::vector<double> samples() const override { return g_->samples(); }
  const char* kind() const override { return g_->kind(); }
  bool thread_safe() const override { return g_->thread_safe(); }

 private:
  std::shared_ptr<const BoundaryGeometry> g_;
  std::shared_ptr<Counts> c_;
};

TEST(CadBoundaryQueries, OnlyProjectionsReachTheCadAFewPerBoundaryVertex) {
  // A box with a slanted square hole (10 planar surfaces, like Gmsh's t2: the input mesh lies
  // on the CAD, so no Hausdorff check needs it).
  const std::string geo = testing::TempDir() + "/holed_box.geo";
  {
    std::ofstream f(geo);
    f << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 2, 1, 1};\n"
         "Box(2) = {0.5, 0.3, -0.1, 0.4, 0.4, 1.2};\n"
         "Rotate {{0, 0, 1}, {0.7, 0.5, 0}, Pi / 6} { Volume{2}; }\n"
         "BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; }\n"
         "Mesh.MeshSizeMax = 0.2;\nMesh.MeshSizeMin = 0.2;\n";
  }
  GmshSession session;
  gmsh::open(geo);
  gmsh::model::mesh::generate(3);
  MeshData d = mesh_from_gmsh(3, "holed_box");
  ASSERT_TRUE(gmsh_model_has_cad(d.tet));
  auto counts = std::make_shared<Counts>();
  OptimizeOptions o;
  o.max_iterations = 10;
  o.auto_refine = false;  // one run: the queries per movable vertex of one run are bounded
  o.boundary_model = [counts](const TetMesh& m, const BoundaryModelOptions& bo) {
    BoundaryModel b = make_gmsh_cad_boundary_if_cad(m, bo);
    if (b.geometry) b.geometry = std::make_shared<CountingGeometry>(b.geometry, counts);
    return b;
  };
  const OptimizeResult r = optimize(d, o);
  ASSERT_EQ(r.boundary_geometry, "cad");
  ASSERT_GT(r.nb_boundary_moved, 0);
  const long movable = r.nb_surface_vertices + r.nb_curve_vertices;
  EXPECT_EQ(counts->distances.load(), 0) << "a Hausdorff check went to the CAD";
  // The projections: the constrained CVT's rounds, the max-min's line searches and the final
  // check: 15 per movable vertex here, 19 on t2 (11267 for 599); the slow path asked every
  // surface for each of ~40 samples per tried move: on t2 about 74 s / 45 us a query, some
  // 2,700 per movable vertex.
  std::printf("CAD queries: %ld for %ld movable vertices\n", counts->projections.load(), movable);
  EXPECT_LE(counts->projections.load(), 30 * movable)
      << counts->projections.load() << " projections for " << movable << " movable vertices";
}

}  // namespace
}  // namespace cvtmesh
