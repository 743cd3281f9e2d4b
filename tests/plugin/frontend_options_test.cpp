// One bad value through two front ends' option paths — the GUI/ONELAB panel (read_panel on a
// tree holding tolerance -1) and the CLI (--tolerance -1) — refused with the message of the core's
// validate(). (Python: tests/plugin/scripting_test.py compares its message with the CLI's.)
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "core/pipeline/option_schema.h"
#include "core/pipeline/optimize.h"
#include "plugin/panel.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

// A ONELAB tree in memory.
class MapTree : public OnelabTree {
 public:
  void set(const OnelabParam& p) override { params[p.name] = p; }
  std::optional<double> number(const std::string& name) override {
    auto it = params.find(name);
    if (it == params.end() || it->second.is_string) return std::nullopt;
    return it->second.number;
  }
  std::optional<std::string> string(const std::string& name) override {
    auto it = params.find(name);
    if (it == params.end() || !it->second.is_string) return std::nullopt;
    return it->second.text;
  }
  void info(const std::string&) override {}
  void error(const std::string&) override {}
  void progress(const std::string&) override {}
  std::map<std::string, OnelabParam> params;
};

std::string core_message_for_tolerance(double t) {
  OptimizeOptions o;
  o.tolerance = t;
  try {
    validate(o, 3);
  } catch (const OptionError& e) {
    return e.what();
  }
  return "";
}

TEST(FrontEndOptions, ThePanelRefusesABadToleranceWithTheCoreMessage) {
  MapTree tree;
  plugin::define_panel(tree, 3);
  const std::string tol = plugin::kGroup + "/2Tolerance";
  ASSERT_TRUE(tree.number(tol).has_value());
  // The schema's default, resolved for the panel's dimension (-1 stands for it in the API).
  EXPECT_EQ(*tree.number(tol), resolve(OptimizeOptions{}, 3).tolerance);
  EXPECT_NO_THROW(plugin::read_panel(tree));
  tree.params[tol].number = -2;
  const std::string expected = core_message_for_tolerance(-2);
  ASSERT_FALSE(expected.empty());
  try {
    plugin::read_panel(tree);
    ADD_FAILURE() << "tolerance -2 accepted by the panel";
  } catch (const OptionError& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
}

TEST(FrontEndOptions, TheCliRefusesABadToleranceWithTheCoreMessageAndWritesNothing) {
  const std::string dir = testing::temp_dir();
  const std::string out = dir + "/out.msh";
  std::string log;
  const int rc =
      testing::run(testing::cli_path() + " optimize " + testing::geo_path("cube_sphere.geo") +
                       " -o " + out + " --tolerance -2",
                   &log);
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find(core_message_for_tolerance(-2)), std::string::npos) << log;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace cvtmesh
