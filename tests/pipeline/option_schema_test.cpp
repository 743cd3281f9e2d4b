// The option schema (core/pipeline/option_schema.h) and the method registry: defaults valid,
// every range enforced by validate() with a message naming the option, the value and the range,
// optimize() refusing before it touches the mesh, dimension rules, resolution of the defaults.
#include "core/pipeline/option_schema.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "core/pipeline/method_registry.h"
#include "core/pipeline/optimize.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::string refusal(const OptimizeOptions& o, int dim) {
  try {
    validate(o, dim);
  } catch (const OptionError& e) {
    return e.what();
  }
  return "";
}

TEST(OptionSchema, DefaultsAreValidInEveryDimension) {
  for (int dim : {0, 2, 3}) EXPECT_EQ(refusal(OptimizeOptions{}, dim), "") << dim;
  std::set<std::string> names, flags;
  for (const OptionSpec& s : option_schema()) {
    EXPECT_TRUE(names.insert(s.name).second) << "option declared twice: " << s.name;
    if (!s.flag.empty()) EXPECT_TRUE(flags.insert(s.flag).second) << s.flag;
    EXPECT_FALSE(s.help.empty()) << s.name;
    EXPECT_NE(describe(s).find("default"), std::string::npos) << s.name;
  }
}

TEST(OptionSchema, EveryNumberBelowOrAboveItsRangeIsRefusedByName) {
  int checked = 0;
  for (const OptionSpec& s : option_schema()) {
    if (std::holds_alternative<std::string OptimizeOptions::*>(s.field) ||
        std::holds_alternative<bool OptimizeOptions::*>(s.field))
      continue;
    const int dim = s.dims == kDim2 ? 2 : 3;
    for (double bad : {s.min - 2, s.max + 1}) {
      if (!std::isfinite(bad)) continue;
      if (s.has_special && bad == s.special) continue;
      OptimizeOptions o;
      try {
        set_number(s, o, bad);  // may refuse already (outside the field's type)
        validate(o, dim);
        ADD_FAILURE() << s.name << " = " << bad << " accepted";
      } catch (const OptionError& e) {
        EXPECT_EQ(e.option(), s.name);
        const std::string m = e.what();
        EXPECT_NE(m.find(s.name), std::string::npos) << m;
        EXPECT_NE(m.find(s.flag), std::string::npos) << m;
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 15);
}

TEST(OptionSchema, TheMessageNamesOptionValueAndRange) {
  OptimizeOptions o;
  o.relaxation = -2;
  EXPECT_EQ(refusal(o, 3),
            "invalid value -2 for option relaxation (--relaxation): expected a number in "
            "[0.05, 1.95]");
  o = {};
  o.lbfgs_memory = -3;
  EXPECT_NE(refusal(o, 3).find("or -1 (default)"), std::string::npos);
  o.lbfgs_memory = -1;  // the documented "dimension's default"
  EXPECT_EQ(refusal(o, 3), "");
  o = {};
  o.tolerance = std::nan("");
  EXPECT_NE(refusal(o, 3), "");
  o = {};
  o.sizing = "fancy";  // not a keyword: the path of a reference file, which was not read
  EXPECT_NE(refusal(o, 3).find("'fancy'"), std::string::npos);
  EXPECT_NE(refusal(o, 3).find("reference file"), std::string::npos);
  auto ref = std::make_shared<MeshData>();
  ref->dim = 2;
  o.sizing_reference = ref;  // read, but of the other dimension
  EXPECT_NE(refusal(o, 3).find("the reference is a 2D mesh"), std::string::npos);
  EXPECT_EQ(refusal(o, 2), "");
  o = {};
  o.regions = "1, 3";
  EXPECT_EQ(refusal(o, 3), "");
  o.regions = "1,x";
  EXPECT_NE(refusal(o, 3).find("--regions"), std::string::npos);
  EXPECT_NE(refusal(o, 2).find("--regions"), std::string::npos);
  o = {};
  o.sizing = "function";  // needs a size function
  EXPECT_NE(refusal(o, 3).find("size_function"), std::string::npos);
}

TEST(OptionSchema, OptionsOfTheOtherDimensionAndWrongMethodsAreRefused) {
  OptimizeOptions o;
  o.hops = 3;
  EXPECT_NE(refusal(o, 3).find("a 2D option"), std::string::npos);
  EXPECT_EQ(refusal(o, 2), "");
  o = {};
  o.swap_below = 0.5;
  EXPECT_NE(refusal(o, 2).find("a 3D option"), std::string::npos);
  o = {};
  o.method = "dl";
  EXPECT_NE(refusal(o, 3).find("not a 3D method"), std::string::npos);
  EXPECT_EQ(refusal(o, 2), "");
  o.method = "no-such";
  EXPECT_NE(refusal(o, 0).find("unknown method"), std::string::npos);
}

TEST(OptionSchema, TextAndWholeNumberConversions) {
  OptimizeOptions o;
  const OptionSpec& it = *find_option("max_iterations");
  EXPECT_THROW(set_text(it, o, "ten"), OptionError);
  EXPECT_THROW(set_text(it, o, "12x"), OptionError);
  EXPECT_THROW(set_number(it, o, 2.5), OptionError);
  set_text(it, o, "12");
  EXPECT_EQ(o.max_iterations, 12);
  const OptionSpec& maxmin = *find_option("--no-polish-maxmin");
  EXPECT_EQ(maxmin.name, "polish_maxmin");
  set_text(maxmin, o, "false");
  EXPECT_FALSE(o.polish_maxmin);
  EXPECT_THROW(set_number(maxmin, o, 0.5), OptionError);
  EXPECT_EQ(value_text(*find_option("relaxation"), OptimizeOptions{}), "1.5");
}

TEST(OptionSchema, ResolveGivesEachDimensionItsDefaults) {
  OptimizeOptions o;
  o.method = "";
  EXPECT_EQ(resolve(o, 3).method, default_method(3));
  EXPECT_EQ(resolve(o, 2).method, default_method(2));
  EXPECT_EQ(resolve(OptimizeOptions{}, 2).method, "cvdt");  // the 3D default name in 2D
  EXPECT_EQ(resolve(OptimizeOptions{}, 3).lbfgs_memory, 5);
  EXPECT_EQ(resolve(OptimizeOptions{}, 2).lbfgs_memory, 0);
  // Lloyd's stop: 3D as before; 2D converges further (its moves stay small long before the CVT).
  EXPECT_EQ(resolve(OptimizeOptions{}, 3).max_iterations, 100);
  EXPECT_EQ(resolve(OptimizeOptions{}, 3).tolerance, 1e-5);
  EXPECT_EQ(resolve(OptimizeOptions{}, 2).max_iterations, 1000);
  EXPECT_EQ(resolve(OptimizeOptions{}, 2).tolerance, 1e-8);
  OptimizeOptions set;  // a value the user gave is kept
  set.max_iterations = 7, set.tolerance = 0;
  EXPECT_EQ(resolve(set, 2).max_iterations, 7);
  EXPECT_EQ(resolve(set, 2).tolerance, 0);
  OptimizeOptions plain;
  apply_preset("plain (paper)", plain);
  EXPECT_EQ(plain.lbfgs_memory, 0);
  EXPECT_EQ(plain.anderson_depth, 0);
  EXPECT_EQ(plain.relaxation, 1.0);
  EXPECT_THROW(apply_preset("turbo", plain), OptionError);
}

TEST(MethodRegistry, EveryMethodIsListedOnceAndRunnable) {
  EXPECT_EQ(methods_for_dim(2), (std::vector<std::string>{"cvdt", "cvdt+swap", "dl", "wdl"}));
  EXPECT_EQ(default_method(3), "cvdt+swap+smooth");
  std::set<std::pair<int, std::string>> seen;
  for (const MethodInfo& m : method_registry()) {
    EXPECT_TRUE(seen.insert({m.dim, m.name}).second) << m.name;
    EXPECT_EQ(m.run3 != nullptr, m.dim == 3) << m.name;
    EXPECT_NE(methods_help(m.dim).find(m.name + " ("), std::string::npos);
  }
}

TEST(OptionSchema, OptimizeRefusesABadValueBeforeTouchingTheMesh) {
  MeshData d = testing::cube_sphere(0.2, 0.15);
  const std::vector<double> before = d.tet.xyz;
  OptimizeOptions o;
  o.max_iterations = -3;
  EXPECT_THROW(optimize(d, o), OptionError);
  o = {};
  o.tolerance = -2;  // -1 means the dimension's default
  EXPECT_THROW(optimize(d, o), OptionError);
  EXPECT_EQ(d.tet.xyz, before);
}

}  // namespace
}  // namespace cvtmesh
