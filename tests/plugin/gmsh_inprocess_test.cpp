// gmsh_optimize / gmsh_quality on the current Gmsh model of this process (in-process scripting):
// the model keeps its entities and physical groups, boundary nodes stay put, the mesh Gmsh holds
// afterwards is the optimized one (its quality is what the result reports), views are replaced
// and not piled up, and errors are typed and leave the model alone.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "plugin/gmsh_inprocess.h"
#include "core/pipeline/option_schema.h"
#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/pipeline/optimize.h"
#include "core/quality/quality_stats.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

using Group = std::tuple<int, int, std::string, std::vector<int>>;  // dim, tag, name, entities

std::vector<Group> physical_groups() {
  std::vector<Group> out;
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups);
  for (const auto& [d, t] : groups) {
    std::string name;
    std::vector<int> ents;
    gmsh::model::getPhysicalName(d, t, name);
    gmsh::model::getEntitiesForPhysicalGroup(d, t, ents);
    out.emplace_back(d, t, name, ents);
  }
  return out;
}

gmsh::vectorpair entities() {
  gmsh::vectorpair e;
  gmsh::model::getEntities(e);
  return e;
}

// Node tag -> coordinates, for the nodes classified on entities of dimension <= max_dim.
std::map<std::size_t, std::vector<double>> nodes(int max_dim) {
  std::map<std::size_t, std::vector<double>> out;
  for (const auto& [d, t] : entities()) {
    if (d > max_dim) continue;
    std::vector<std::size_t> tags;
    std::vector<double> xyz, uv;
    gmsh::model::mesh::getNodes(tags, xyz, uv, d, t, false, false);
    for (std::size_t i = 0; i < tags.size(); ++i)
      out[tags[i]] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  }
  return out;
}

std::size_t nb_views() {
  std::vector<int> tags;
  gmsh::view::getTags(tags);
  return tags.size();
}

// A Gmsh session owned by the test (as a script's would be), a coarse cube_sphere meshed in 3D.
class GmshInProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    set_gmsh_initialized_by_caller(true);
  }
  void TearDown() override {
    gmsh::finalize();
    set_gmsh_initialized_by_caller(false);
  }
  static void open_cube_sphere(bool two_regions = false, bool mesh = true) {
    gmsh::option::setNumber("Mesh.MeshSizeFactor", 2.5);
    gmsh::option::setNumber("Mesh.RandomSeed", 1);
    // DefineConstant takes a value already in the ONELAB database.
    gmsh::onelab::setNumber("cvtmesh/Geometry/ball as a region", {two_regions ? 1.0 : 0.0});
    gmsh::open(testing::geo_path("cube_sphere.geo"));
    if (mesh) gmsh::model::mesh::generate(3);
  }
};

TEST_F(GmshInProcess, EveryMethodOptimizesTheCurrentModelInPlace) {
  const auto methods = methods_for_dim(3);
  ASSERT_FALSE(methods.empty());
  for (const auto& method : methods) {
    SCOPED_TRACE(method);
    gmsh::clear();
    open_cube_sphere(true);  // two volumes sharing the ball's surface
    const auto groups = physical_groups();
    const auto ents = entities();
    const auto boundary = nodes(2);
    const auto all_before = nodes(3);
    ASSERT_GE(groups.size(), 3u);

    GmshOptimizeOptions o;
    o.optimize.method = method;
    o.optimize.max_iterations = 4;
    o.optimize.fix_boundary = true;  // the fixed-boundary contract (free boundary: tests/boundary/)
    o.quality_views = true;
    const GmshOptimizeResult r = gmsh_optimize(o);

    EXPECT_EQ(r.method, method);
    EXPECT_EQ(r.dim, 3);
    EXPECT_EQ(physical_groups(), groups);
    EXPECT_EQ(entities(), ents);
    // Boundary and interface nodes keep their tags, classification and coordinates.
    EXPECT_EQ(nodes(2), boundary);
    // Quality rose (all methods are meant to improve a Gmsh mesh on average).
    EXPECT_GT(r.result.after.q_avg, r.result.before.q_avg);
    // The model Gmsh holds now is the optimized mesh: re-read, it has the reported quality.
    const MeshData now = mesh_from_gmsh(3);
    const QualityStats s = quality_stats(now.tet, "now");
    EXPECT_EQ(s.nb_elements, r.result.after.nb_elements);
    EXPECT_NEAR(s.q_avg, r.result.after.q_avg, 1e-12);
    EXPECT_NEAR(s.q_min, r.result.after.q_min, 1e-12);
    if (method != "swap") {  // swaps only change connectivity
      const auto all_after = nodes(3);
      int moved = 0;
      for (const auto& [tag, x] : all_after) {
        auto it = all_before.find(tag);
        if (it != all_before.end() && it->second != x) ++moved;
      }
      EXPECT_GT(moved, 0);
    }
    // The views hold one value per tet, the first being Q.
    ASSERT_EQ(r.views.size(), 3u);
    std::string type;
    std::vector<std::size_t> tags;
    std::vector<std::vector<double>> data;
    double time = 0;
    int nc = 0;
    gmsh::view::getModelData(r.views[0], 0, type, tags, data, time, nc);
    EXPECT_EQ(type, "ElementData");
    ASSERT_EQ(static_cast<long>(data.size()), r.result.after.nb_elements);
    double q_min = 2;
    for (const auto& v : data) q_min = std::min(q_min, v.at(0));
    EXPECT_NEAR(q_min, r.result.after.q_min, 1e-12);
  }
}

// The default method on an OCC ball in the current model: the free boundary moves on the CAD
// sphere (result.boundary_geometry "cad"), and every node Gmsh holds on the sphere's surface and
// seam afterwards is on the exact sphere to 1e-12 (the ones the surface coarsening removed are
// gone from the model); the points (poles) never move.
TEST_F(GmshInProcess, DefaultMethodMovesTheBoundaryOnTheCadSphereTo1e12) {
  gmsh::model::add("ball");
  gmsh::model::occ::addSphere(0.1, 0.2, 0.3, 1);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.3);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0.3);
  gmsh::model::mesh::generate(3);
  const auto boundary = nodes(2);
  const auto points = nodes(0);
  GmshOptimizeOptions o;
  o.optimize.max_iterations = 10;
  const GmshOptimizeResult r = gmsh_optimize(o);
  ASSERT_TRUE(r.result.boundary_free);
  EXPECT_EQ(r.result.boundary_geometry, "cad");
  EXPECT_GT(r.result.nb_boundary_moved, 0);
  // The surface coarsening may remove surface nodes (they are gone from the model, not left as
  // orphans); no node is new.
  const auto after = nodes(2);
  ASSERT_EQ(after.size(), boundary.size() - static_cast<std::size_t>(r.result.nb_boundary_removed));
  int moved = 0;
  for (const auto& [tag, x] : after) {
    ASSERT_TRUE(boundary.count(tag)) << "node " << tag << " is new";
    const double rad = std::sqrt((x[0] - .1) * (x[0] - .1) + (x[1] - .2) * (x[1] - .2) +
                                 (x[2] - .3) * (x[2] - .3));
    EXPECT_LE(std::fabs(rad - 1), 1e-12) << "node " << tag;
    moved += boundary.at(tag) != x;
  }
  EXPECT_GT(moved, 0);
  EXPECT_EQ(nodes(0), points);
}

// An order-2 OCC disk in the current model (tri6 + line3): optimized in place, it stays order 2,
// its interior mid-edge nodes straight, its boundary ones on the circle (kept: the 2D boundary
// does not move), and the notes say how the nodes were placed.
TEST_F(GmshInProcess, PlanarOrder2DiskStaysOrder2) {
  gmsh::model::add("disk");
  gmsh::model::occ::addDisk(0.1, 0.2, 0, 1, 1);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", 0.2);
  gmsh::model::mesh::generate(2);
  gmsh::model::mesh::setOrder(2);
  const auto before = nodes(2);
  GmshOptimizeOptions o;
  o.optimize.max_iterations = 10;
  const GmshOptimizeResult r = gmsh_optimize(o);
  EXPECT_EQ(r.dim, 2);
  bool noted = false;
  for (const auto& n : r.result.notes) noted |= n.find("order-2 mesh:") != std::string::npos;
  EXPECT_TRUE(noted);
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 2);
  EXPECT_EQ(types, std::vector<int>{9});
  gmsh::model::mesh::getElementTypes(types, 1);
  EXPECT_EQ(types, std::vector<int>{8});
  const auto after = nodes(2);
  // Interior: tri6 mid-edge nodes (classified on the surface) are straight midpoints.
  std::vector<std::size_t> tags, nd;
  gmsh::model::mesh::getElementsByType(9, tags, nd);
  ASSERT_FALSE(tags.empty());
  std::map<std::size_t, std::vector<double>> interior;
  {
    std::vector<std::size_t> t;
    std::vector<double> xyz, uv;
    gmsh::model::mesh::getNodes(t, xyz, uv, 2, 1, false, false);
    for (std::size_t i = 0; i < t.size(); ++i)
      interior[t[i]] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  }
  static const int kEdge[3][2] = {{0, 1}, {1, 2}, {2, 0}};
  double worst = 0;
  int moved = 0;
  for (std::size_t e = 0; e < tags.size(); ++e)
    for (int k = 0; k < 3; ++k) {
      auto m = interior.find(nd[6 * e + 3 + k]);
      if (m == interior.end()) continue;
      const auto& a = after.at(nd[6 * e + kEdge[k][0]]);
      const auto& b = after.at(nd[6 * e + kEdge[k][1]]);
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::fabs(m->second[c] - 0.5 * (a[c] + b[c])));
    }
  for (const auto& [tag, x] : interior) moved += before.count(tag) && before.at(tag) != x;
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(moved, 0);
  // Boundary: the line3's nodes on the circle.
  std::vector<std::size_t> line_tags, line_nodes;
  gmsh::model::mesh::getElementsByType(8, line_tags, line_nodes);
  ASSERT_FALSE(line_tags.empty());
  for (std::size_t e = 0; e < line_tags.size(); ++e) {
    const auto& x = after.at(line_nodes[3 * e + 2]);
    EXPECT_LE(std::fabs(std::hypot(x[0] - 0.1, x[1] - 0.2) - 1), 1e-9);
  }
}

TEST_F(GmshInProcess, RunningAgainReplacesTheQualityViews) {
  const auto methods = methods_for_dim(3);
  ASSERT_FALSE(methods.empty());
  open_cube_sphere();
  GmshOptimizeOptions o;
  o.optimize.method = methods.front();
  o.optimize.max_iterations = 2;
  o.quality_views = true;
  gmsh_optimize(o);
  ASSERT_EQ(nb_views(), 3u);
  const GmshQualityResult q = gmsh_quality(o);
  EXPECT_EQ(nb_views(), 3u);  // stale views of the first run removed
  EXPECT_EQ(q.views.size(), 3u);
  const GmshOptimizeResult r = gmsh_optimize(o);
  EXPECT_EQ(nb_views(), 3u);
  // The second run starts from the first run's result, measured by gmsh_quality.
  EXPECT_NEAR(r.result.before.q_avg, q.stats.q_avg, 1e-12);
  // Without views, the old ones (on elements that changed) go too.
  o.quality_views = false;
  gmsh_optimize(o);
  EXPECT_EQ(nb_views(), 0u);
}

TEST_F(GmshInProcess, EmptyMethodPicksTheFirstForTheDimension) {
  open_cube_sphere();
  GmshOptimizeOptions o;
  o.optimize.method = "";
  o.optimize.max_iterations = 1;
  EXPECT_EQ(gmsh_optimize(o).method, methods_for_dim(3).front());
}

TEST_F(GmshInProcess, ModelWithoutMeshIsAnErrorUnlessGenerateIsAsked) {
  open_cube_sphere(false, /*mesh=*/false);
  GmshOptimizeOptions o;
  o.optimize.method = methods_for_dim(3).front();
  o.optimize.max_iterations = 1;
  try {
    gmsh_optimize(o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has no mesh"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(nodes(3).empty());
  o.generate = true;
  const GmshOptimizeResult r = gmsh_optimize(o);
  EXPECT_GT(r.result.after.nb_elements, 0);
  EXPECT_FALSE(nodes(3).empty());
}

// A surface-only model (an open sphere octant: triangles that bound no volume) is optimized in
// place like a volume mesh: its triangles on the CAD sphere, its lines and points kept, the quality
// Gmsh holds afterwards the result's and not worse, the views on the triangles.
TEST_F(GmshInProcess, SurfaceOnlyModelIsOptimizedInPlace) {
  const std::string geo = testing::temp_dir() + "/octant.geo";
  std::FILE* f = std::fopen(geo.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs(
      "Point(1) = {0, 0, 0, 0.2};\nPoint(2) = {1, 0, 0, 0.2};\nPoint(3) = {0, 1, 0, 0.2};\n"
      "Point(4) = {0, 0, 1, 0.05};\nCircle(1) = {2, 1, 3};\nCircle(2) = {3, 1, 4};\n"
      "Circle(3) = {4, 1, 2};\nCurve Loop(1) = {1, 2, 3};\nSurface(1) = {1};\n"
      "Physical Surface(\"octant\", 5) = {1};\n",
      f);
  std::fclose(f);
  gmsh::open(geo);
  gmsh::model::mesh::generate(2);
  const auto corners = nodes(0);  // the arcs' ends and the sphere's centre (Point 1)
  const auto curves = nodes(1);
  const auto surface = nodes(2);
  const auto groups = physical_groups();
  GmshOptimizeOptions o;
  o.quality_views = true;
  const GmshQualityResult before = gmsh_quality(o);
  const GmshOptimizeResult r = gmsh_optimize(o);
  EXPECT_EQ(r.dim, 3);
  EXPECT_EQ(physical_groups(), groups);
  EXPECT_EQ(nodes(0), corners);  // the corners fixed
  // Every node of the surface and its arcs on the CAD sphere, the arcs' in their planes; the
  // curve nodes keep their tags (they slide along their arcs).
  const auto after_curves = nodes(1);
  ASSERT_EQ(after_curves.size(), curves.size());
  int moved = 0;
  for (const auto& [tag, p] : after_curves) {
    EXPECT_EQ(curves.count(tag), 1u) << tag;
    if (corners.count(tag)) continue;
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 1e-9) << tag;
    EXPECT_NEAR(std::min({std::abs(p[0]), std::abs(p[1]), std::abs(p[2])}), 0.0, 1e-12) << tag;
  }
  for (const auto& [tag, p] : nodes(2)) {
    if (after_curves.count(tag)) continue;
    EXPECT_NEAR(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 1.0, 1e-9) << tag;
    const auto it = surface.find(tag);
    moved += it != surface.end() && it->second != p;
  }
  EXPECT_GT(moved, 0);
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 2, 1);
  EXPECT_EQ(types, std::vector<int>{2});  // triangles only
  std::vector<std::size_t> tri_tags, tri_nodes;
  gmsh::model::mesh::getElementsByType(2, tri_tags, tri_nodes, 1);
  o.quality_views = false;
  const GmshQualityResult after = gmsh_quality(o);
  EXPECT_EQ(after.stats.nb_elements, static_cast<long>(tri_tags.size()));
  EXPECT_EQ(after.stats.nb_elements, r.result.after.nb_elements);
  EXPECT_NEAR(after.stats.q_min, r.result.after.q_min, 1e-12);
  EXPECT_GE(after.stats.q_min, before.stats.q_min - 1e-12);
  ASSERT_EQ(r.views.size(), 3u);
  std::string type;
  std::vector<std::size_t> view_tags;
  std::vector<std::vector<double>> data;
  double time = 0;
  int nc = 0;
  gmsh::view::getModelData(r.views.front(), 0, type, view_tags, data, time, nc);
  std::sort(view_tags.begin(), view_tags.end());
  std::sort(tri_tags.begin(), tri_tags.end());
  EXPECT_EQ(view_tags, tri_tags);
}

// A .msh saved with physical groups holds only their elements: reopened in a script, the two-region
// cube_sphere lacks the cube faces (no group). The in-process path restores them as the CLI's
// reader does, so the model optimizes instead of being refused as "boundary not closed".
TEST_F(GmshInProcess, ModelOpenedFromAMshWithPhysicalGroupsOnlyOptimizes) {
  open_cube_sphere(true);
  std::size_t nb_tris_all = 0;
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, 2);
    for (const auto& t : tags) nb_tris_all += t.size();
  }
  const std::string path = ::testing::TempDir() + "cvtmesh_groups_only_" +
                           std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                           ".msh";
  gmsh::option::setNumber("Mesh.SaveAll", 0);
  gmsh::write(path);
  gmsh::clear();
  gmsh::open(path);
  std::size_t nb_tris_read = 0;
  {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, 2);
    for (const auto& t : tags) nb_tris_read += t.size();
  }
  ASSERT_LT(nb_tris_read, nb_tris_all);  // the file really lacks the cube's faces
  GmshOptimizeOptions o;
  o.optimize.max_iterations = 4;
  const GmshOptimizeResult r = gmsh_optimize(o);
  EXPECT_EQ(r.dim, 3);
  EXPECT_GT(r.result.after.q_min, r.result.before.q_min);
  const MeshData now = mesh_from_gmsh(3);
  EXPECT_EQ(quality_stats(now.tet, "now").nb_elements, r.result.after.nb_elements);
  std::remove(path.c_str());
}

TEST_F(GmshInProcess, EmptyModelIsAnError) {
  GmshOptimizeOptions o;
  o.generate = true;
  EXPECT_THROW(gmsh_optimize(o), InputError);
}

TEST_F(GmshInProcess, UnknownMethodLeavesTheModelUnchanged) {
  open_cube_sphere();
  const auto before = nodes(3);
  GmshOptimizeOptions o;
  o.optimize.method = "no-such-method";
  EXPECT_THROW(gmsh_optimize(o), OptionError);
  EXPECT_EQ(nodes(3), before);
}

TEST_F(GmshInProcess, AbortFromProgressLeavesTheModelUnchanged) {
  open_cube_sphere();
  const auto before = nodes(3);
  GmshOptimizeOptions o;
  o.optimize.method = methods_for_dim(3).front();
  o.optimize.progress = [](const OptimizeProgress&) { throw std::runtime_error("stop"); };
  EXPECT_THROW(gmsh_optimize(o), std::runtime_error);
  EXPECT_EQ(nodes(3), before);
}

}  // namespace
}  // namespace cvtmesh
