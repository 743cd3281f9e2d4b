// What the GUI shows after a run, checked through Gmsh's option and view API in this process
// (no window needed): the histogram is a graph view (View.Type 2) whose points are the
// histogram; the Q view's colour range is its own data range; the cut faces the camera for any
// view angles; the views are marked stale when the mesh or the options change, and the next run
// removes them. Also the pure camera_direction / camera_cut_plane and the .geo text of the cut.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/io/camera_cut.h"
#include "core/io/gmsh_session.h"
#include "core/quality/quality_histogram.h"
#include "plugin/gmsh_gui.h"
#include "plugin/gmsh_inprocess.h"
#include "plugin/panel.h"
#include "plugin/stale_watch.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::string view_name(int tag) {
  std::string n;
  gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(tag)) + "].Name", n);
  return n;
}
double view_number(int tag, const std::string& option) {
  double v = 0;
  gmsh::option::getNumber("View[" + std::to_string(gmsh::view::getIndex(tag)) + "]." + option, v);
  return v;
}
std::vector<std::string> view_names() {
  std::vector<int> tags;
  gmsh::view::getTags(tags);
  std::vector<std::string> out;
  for (int t : tags) out.push_back(view_name(t));
  return out;
}

TEST(CameraCut, FacesTheCameraForAnyViewAngles) {
  // Gmsh's default view looks down -z: the plane is z = const, the far half (z below) kept.
  const auto n0 = camera_direction(0, 0, 0);
  EXPECT_NEAR(n0[0], 0, 1e-15);
  EXPECT_NEAR(n0[1], 0, 1e-15);
  EXPECT_NEAR(n0[2], 1, 1e-15);
  const auto p = camera_cut_plane(n0, {0.5, 0.5, 0.5});
  auto kept = [&p](double x, double y, double z) {
    return p[0] * x + p[1] * y + p[2] * z + p[3] >= 0;
  };
  EXPECT_TRUE(kept(0.5, 0.5, 0.2));
  EXPECT_FALSE(kept(0.5, 0.5, 0.8));
  // For any angles: a unit vector, and the eye-space z axis of Rx Ry Rz mapped back (rotating the
  // direction by the model-view rotation gives (0, 0, 1)).
  for (double rx : {-65.0, 0.0, 30.0, 120.0})
    for (double ry : {-40.0, 0.0, 75.0})
      for (double rz : {-115.0, 0.0, 10.0}) {
        const auto n = camera_direction(rx, ry, rz);
        EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-12);
        const double d = M_PI / 180;
        auto rot = [](int axis, double a, std::array<double, 3> v) {
          const double c = std::cos(a), s = std::sin(a);
          const int i = (axis + 1) % 3, j = (axis + 2) % 3;
          std::array<double, 3> w = v;
          w[i] = c * v[i] - s * v[j];
          w[j] = s * v[i] + c * v[j];
          return w;
        };
        // eye = Rx Ry Rz model: apply Rz, then Ry, then Rx.
        const auto e = rot(0, rx * d, rot(1, ry * d, rot(2, rz * d, n)));
        EXPECT_NEAR(e[0], 0, 1e-12);
        EXPECT_NEAR(e[1], 0, 1e-12);
        EXPECT_NEAR(e[2], 1, 1e-12);
      }
  // The .geo text computes the same from Gmsh's own angles.
  const std::string geo = camera_cut_geo({1, 2, 3}, "cvt_q");
  EXPECT_NE(geo.find("General.RotationX"), std::string::npos);
  EXPECT_NE(geo.find("View[cvt_q].Clip = 1;"), std::string::npos);
}

class GuiViews : public ::testing::Test {
 protected:
  void SetUp() override {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    set_gmsh_initialized_by_caller(true);
    gmsh::option::setNumber("Mesh.MeshSizeFactor", 2.5);
    gmsh::option::setNumber("Mesh.RandomSeed", 1);
    gmsh::open(testing::geo_path("cube_sphere.geo"));
    gmsh::model::mesh::generate(3);
  }
  void TearDown() override {
    gmsh::finalize();
    set_gmsh_initialized_by_caller(false);
  }
  GmshOptimizeResult run() {
    GmshOptimizeOptions o;
    o.optimize.method = "cvdt+swap";
    o.optimize.max_iterations = 3;
    o.quality_views = true;
    return gmsh_optimize(o);
  }
};

TEST_F(GuiViews, HistogramIsAGraphOfTheHistogram) {
  const auto before = quality_histogram({0.2, 0.4, 0.4, 0.9}, 10, "before");
  const auto after = quality_histogram({0.8, 0.85, 0.9, 0.95}, 10, "after");
  const int tag = gui_add_histogram_view({before, after}, kHistogramViewName);
  EXPECT_EQ(view_name(tag), kHistogramViewName);
  EXPECT_EQ(view_number(tag, "Type"), 2);        // a 2D graph
  EXPECT_EQ(view_number(tag, "NbTimeStep"), 2);  // one curve per series
  std::vector<std::string> types;
  std::vector<int> counts;
  std::vector<std::vector<double>> data;
  gmsh::view::getListData(tag, types, counts, data);
  ASSERT_EQ(types.size(), 1u);
  EXPECT_EQ(types[0], "SP");
  ASSERT_EQ(counts[0], 20);  // two points per bin
  // Point k: x, y, z, then one value per series; x runs over [0, 1] (the curvilinear abscissa is
  // Q), each bin's two points carry its % of elements.
  for (int k = 0; k < 20; ++k) {
    const double* e = &data[0][5 * k];
    EXPECT_NEAR(e[0], (k / 2 + k % 2) / 10.0, 1e-12);
    EXPECT_EQ(e[1], 0);
    EXPECT_EQ(e[2], 0);
    EXPECT_NEAR(e[3], 100 * before.fraction[k / 2], 1e-12);
    EXPECT_NEAR(e[4], 100 * after.fraction[k / 2], 1e-12);
  }
  EXPECT_EQ(view_number(tag, "RangeType"), 2);
  EXPECT_EQ(view_number(tag, "CustomMin"), 0);
  EXPECT_NEAR(view_number(tag, "CustomMax"), 50, 1e-12);  // the highest bin: 2 of 4
}

TEST_F(GuiViews, TheQViewIsShownAloneOverItsRangeAndCutFacingTheCamera) {
  const GmshOptimizeResult r = run();
  ASSERT_EQ(r.views.size(), 3u);
  gmsh::option::setNumber("General.RotationX", -65);
  gmsh::option::setNumber("General.RotationZ", -115);
  gui_show_view(r.views.front(), 0, 0, true);
  const int q = r.views.front();
  EXPECT_EQ(view_number(q, "Visible"), 1);
  EXPECT_EQ(view_number(r.views[1], "Visible"), 0);
  EXPECT_EQ(view_number(q, "RangeType"), 2);
  EXPECT_NEAR(view_number(q, "CustomMin"), r.result.after.q_min, 1e-9);
  EXPECT_DOUBLE_EQ(view_number(q, "CustomMin"), view_number(q, "Min"));
  EXPECT_DOUBLE_EQ(view_number(q, "CustomMax"), view_number(q, "Max"));
  EXPECT_GT(view_number(q, "CustomMin"), 0);  // not [0, 1]
  EXPECT_LT(view_number(q, "CustomMax"), 1);
  EXPECT_EQ(view_number(q, "Clip"), 1);
  double a = 0, b = 0, c = 0, d = 0, rx = 0, ry = 0, rz = 0, mesh_clip = 0;
  gmsh::option::getNumber("General.Clip0A", a);
  gmsh::option::getNumber("General.Clip0B", b);
  gmsh::option::getNumber("General.Clip0C", c);
  gmsh::option::getNumber("General.Clip0D", d);
  gmsh::option::getNumber("General.RotationX", rx);
  gmsh::option::getNumber("General.RotationY", ry);
  gmsh::option::getNumber("General.RotationZ", rz);
  gmsh::option::getNumber("Mesh.Clip", mesh_clip);
  const auto n = camera_direction(rx, ry, rz);
  EXPECT_NEAR(a, -n[0], 1e-12);
  EXPECT_NEAR(b, -n[1], 1e-12);
  EXPECT_NEAR(c, -n[2], 1e-12);
  EXPECT_NEAR(a * 0.5 + b * 0.5 + c * 0.5 + d, 0, 1e-9);  // through the cube's centre
  EXPECT_EQ(mesh_clip, 1);
  // The histogram graph stays visible beside the Q view.
  const int g = gui_add_histogram_view({quality_histogram({0.5}, 20, "x")}, kHistogramViewName);
  gui_show_view(q, 0, 0, true);
  EXPECT_EQ(view_number(g, "Visible"), 1);
}

TEST_F(GuiViews, ViewsAreMarkedStaleWhenTheMeshOrTheOptionsChange) {
  run();
  gui_add_histogram_view({quality_histogram({0.5, 0.7}, 20, "after")}, kHistogramViewName);
  const auto fresh = view_names();
  plugin::StaleWatch w;
  w.arm("options A");
  EXPECT_EQ(w.check("options A"), "");  // nothing changed
  EXPECT_EQ(view_names(), fresh);
  // The options change: every view of ours is renamed "... (stale)", once.
  EXPECT_EQ(w.check("options B"), "options");
  const auto stale = view_names();
  ASSERT_EQ(stale.size(), fresh.size());
  for (std::size_t i = 0; i < stale.size(); ++i) EXPECT_EQ(stale[i], fresh[i] + kStaleSuffix);
  EXPECT_FALSE(w.armed());
  EXPECT_EQ(w.check("options C"), "");
  EXPECT_EQ(view_names(), stale);

  // The next run removes the stale views with the others.
  const GmshOptimizeResult r = run();
  EXPECT_EQ(view_names().size(), r.views.size());
  for (const auto& n : view_names()) EXPECT_EQ(n.find(kStaleSuffix), std::string::npos) << n;

  // The mesh changes (one node moved, as a re-mesh or an edit would): stale too.
  w.arm("options A");
  EXPECT_EQ(w.check("options A"), "");
  std::vector<std::size_t> tags;
  std::vector<double> xyz, uvw;
  gmsh::model::mesh::getNodes(tags, xyz, uvw, 3, -1, false, false);
  ASSERT_FALSE(tags.empty());
  gmsh::model::mesh::setNode(tags.front(), {xyz[0] + 1e-3, xyz[1], xyz[2]}, {});
  EXPECT_EQ(w.check("options A"), "mesh");
  for (const auto& n : view_names()) EXPECT_NE(n.find(kStaleSuffix), std::string::npos) << n;
}

}  // namespace
}  // namespace cvtmesh
