// The .geo scan that refuses scripts starting processes (core/io/geo_scan.h), the runtime guard
// behind it (core/io/process_guard.h), and the CLI's refusal / --allow-system-calls.
#include "core/io/geo_scan.h"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/io/gmsh_session.h"
#include "core/io/process_guard.h"
#include "core/io/read_mesh.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

namespace fs = std::filesystem;

void spit(const fs::path& p, const std::string& text) {
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
}

std::vector<GeoScanFinding> scan_text(
    const std::string& text, const std::vector<std::pair<std::string, std::string>>& set = {}) {
  const fs::path dir = testing::temp_dir();
  spit(dir / "m.geo", text);
  return scan_geo_for_processes((dir / "m.geo").string(), set);
}

TEST(GeoScan, FindsEachProcessCommandWithItsLine) {
  for (const char* cmd : {"SystemCall", "NonBlockingSystemCall", "OnelabRun"}) {
    const auto f = scan_text(std::string("Point(1) = {0, 0, 0};\n") + cmd + " \"touch x\";\n");
    ASSERT_EQ(f.size(), 1u) << cmd;
    EXPECT_EQ(f[0].command, cmd);
    EXPECT_EQ(f[0].line, 2);
    EXPECT_NE(f[0].detail.find("touch x"), std::string::npos);
    EXPECT_NE(geo_scan_message(f).find("line 2"), std::string::npos);
  }
  // Inside a macro, with a comment between the command and its argument.
  EXPECT_EQ(scan_text("Macro M\n  SystemCall/* hidden */\"rm -rf /tmp/x\";\nReturn\n").size(), 1u);
  // Registering a solver program is one too.
  EXPECT_EQ(scan_text("Solver.Executable0 = \"/bin/sh\";\n").size(), 1u);
}

TEST(GeoScan, CommentsAndStringsDoNotFoolIt) {
  EXPECT_TRUE(scan_text("// SystemCall \"touch x\";\n/* OnelabRun \"a\";\n SystemCall */\n"
                        "Printf(\"SystemCall \\\"x\\\" is only text\");\nPoint(1) = {0,0,0};\n")
                  .empty());
  // A string that ends after an escaped quote, then a real command.
  EXPECT_EQ(scan_text("s = \"a\\\"b\"; SystemCall \"x\";\n").size(), 1u);
  // A comment marker inside a string does not start a comment.
  EXPECT_EQ(scan_text("s = \"http://x\"; SystemCall \"y\";\n").size(), 1u);
  // Identifiers are whole words and case-sensitive, as in Gmsh.
  EXPECT_TRUE(scan_text("MySystemCall = 1; systemcall = 2;\n").empty());
}

TEST(GeoScan, FollowsIncludesAndMergesAsGmshResolvesThem) {
  const fs::path dir = testing::temp_dir();
  spit(dir / "sub" / "c.geo", "Point(1) = {0,0,0};\n\nNonBlockingSystemCall \"x\";\n");
  spit(dir / "sub" / "b.geo", "Include \"c.geo\";\n");  // relative to sub/
  spit(dir / "a.geo", "Include StrCat(CurrentDir, \"sub/b.geo\");\n");
  auto f = scan_geo_for_processes((dir / "a.geo").string());
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(fs::path(f[0].file).filename(), "c.geo");
  EXPECT_EQ(f[0].line, 3);
  // Through a string variable, DefineString and the command line's value of it.
  spit(dir / "v.geo", "f = \"sub/b.geo\";\nInclude f;\n");
  EXPECT_EQ(scan_geo_for_processes((dir / "v.geo").string()).size(), 1u);
  spit(dir / "safe.geo", "Point(1) = {0,0,0};\n");
  spit(dir / "d.geo", "g = DefineString[\"safe.geo\", Name \"g\"];\nInclude g;\n");
  EXPECT_TRUE(scan_geo_for_processes((dir / "d.geo").string()).empty());
  EXPECT_EQ(scan_geo_for_processes((dir / "d.geo").string(), {{"g", "sub/b.geo"}}).size(), 1u);
  // Merge of a script (any extension Gmsh parses, e.g. a .pos view) is followed; data is not.
  spit(dir / "view.pos", "View \"v\" { SP(0,0,0){1}; };\nSystemCall \"x\";\n");
  spit(dir / "data.stl", "solid x SystemCall\nendsolid\n");
  spit(dir / "m.geo", "Merge \"data.stl\";\n");
  EXPECT_TRUE(scan_geo_for_processes((dir / "m.geo").string()).empty());
  spit(dir / "p.geo", "Merge \"view.pos\";\n");
  EXPECT_EQ(scan_geo_for_processes((dir / "p.geo").string()).size(), 1u);
  // The model's own option file, which Gmsh reads after it.
  spit(dir / "o.geo", "Point(1) = {0,0,0};\n");
  spit(dir / "o.geo.opt", "OnelabRun \"x\";\n");
  EXPECT_EQ(scan_geo_for_processes((dir / "o.geo").string()).size(), 1u);
  // Include cycles end.
  spit(dir / "loop1.geo", "Include \"loop2.geo\";\n");
  spit(dir / "loop2.geo", "Include \"loop1.geo\";\n");
  EXPECT_TRUE(scan_geo_for_processes((dir / "loop1.geo").string()).empty());
}

TEST(GeoScan, AFileNameItCannotResolveIsRefused) {
  const auto f = scan_text("Include Sprintf(\"part%g.geo\", 1);\n");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].command, "Include");
  EXPECT_NE(f[0].detail.find("computed file name"), std::string::npos);
}

TEST(GeoScan, GmshsTutorialsAndOurModelsHaveNoFinding) {
  int n = 0;
  for (const char* m : {"cube_sphere.geo", "femur.geo", "quad.geo", "washer.geo"}) {
    EXPECT_TRUE(scan_geo_for_processes(testing::geo_path(m)).empty()) << m;
    ++n;
  }
  const fs::path tut = "/usr/share/doc/gmsh-doc/doc/gmsh/tutorial";
  if (fs::exists(tut / "t11.geo")) {
    for (const char* t :
         {"t11.geo", "t12.geo", "t13.geo", "t14.geo", "t15.geo", "t16.geo", "t17.geo", "t18.geo",
          "t19.geo", "t20.geo", "t21.geo", "t6.geo", "t7.geo", "t9.geo"}) {
      EXPECT_TRUE(scan_geo_for_processes((tut / t).string()).empty()) << t;
      ++n;
    }
  }
  EXPECT_GE(n, 4);
}

TEST(ProcessGuard, RefusesSystemAndPopenWhileAliveOnly) {
  const fs::path dir = testing::temp_dir();
  const std::string touch = "touch " + (dir / "ran").string();
  {
    ProcessGuard g;
    EXPECT_EQ(std::system(touch.c_str()), -1);
    EXPECT_EQ(popen(touch.c_str(), "r"), nullptr);
    ASSERT_EQ(g.refused().size(), 2u);
    EXPECT_EQ(g.refused()[0], touch);
  }
  EXPECT_FALSE(fs::exists(dir / "ran"));
  EXPECT_EQ(std::system(touch.c_str()), 0);
  EXPECT_TRUE(fs::exists(dir / "ran"));
}

TEST(ProcessGuard, BlocksGmshsOwnSystemCall) {
  // libgmsh's SystemCall reaches our system(): the guard holds even for what a scan would miss.
  const fs::path dir = testing::temp_dir();
  spit(dir / "evil.geo", "SystemCall \"touch " + (dir / "pwned").string() + "\";\n");
  GmshSession session;
  std::vector<std::string> refused;
  {
    ProcessGuard g;
    gmsh::open((dir / "evil.geo").string());
    refused = g.refused();
  }
  gmsh::model::remove();
  EXPECT_FALSE(fs::exists(dir / "pwned"));
  ASSERT_EQ(refused.size(), 1u);
  EXPECT_NE(refused[0].find("pwned"), std::string::npos);
}

TEST(GeoScanCli, ConvertRefusesAScriptThatRunsAProgramUnlessAllowed) {
  const fs::path dir = testing::temp_dir();
  spit(dir / "part.geo", "SystemCall \"touch pwned\";\n");
  spit(dir / "evil.geo",
       "// looks harmless\nInclude \"part.geo\";\nPoint(1) = {0,0,0}; Point(2) = {1,0,0};\n"
       "Point(3) = {0,1,0}; Point(4) = {0,0,1};\nLine(1) = {1,2}; Line(2) = {2,3}; "
       "Line(3) = {3,1}; Line(4) = {1,4}; Line(5) = {2,4}; Line(6) = {3,4};\n"
       "Curve Loop(1) = {1,2,3}; Plane Surface(1) = {1}; Curve Loop(2) = {1,5,-4};\n"
       "Plane Surface(2) = {2}; Curve Loop(3) = {2,6,-5}; Plane Surface(3) = {3};\n"
       "Curve Loop(4) = {3,4,-6}; Plane Surface(4) = {4};\n"
       "Surface Loop(1) = {1,2,3,4}; Volume(1) = {1};\n");
  std::string log;
  const std::string cd = "cd '" + dir.string() + "' && ";
  int rc = testing::run(cd + testing::cli_path() + " convert evil.geo out.msh", &log);
  EXPECT_EQ(rc, 2) << log;
  EXPECT_NE(log.find("part.geo' line 1: SystemCall"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "pwned"));
  EXPECT_FALSE(fs::exists(dir / "out.msh"));
  rc = testing::run(cd + testing::cli_path() + " convert evil.geo out.msh --allow-system-calls",
                    &log);
  EXPECT_EQ(rc, 0) << log;
  EXPECT_TRUE(fs::exists(dir / "pwned"));
  EXPECT_TRUE(fs::exists(dir / "out.msh"));
}

TEST(GeoScanCli, AStringParameterCannotInjectCode) {
  const fs::path dir = testing::temp_dir();
  std::string log;
  const std::string cmd = "cd '" + dir.string() + "' && " + testing::cli_path() + " convert " +
                          testing::geo_path("cube_sphere.geo") +
                          " out.msh --set-string 'x=a\"; SystemCall \"touch pwned'";
  EXPECT_EQ(testing::run(cmd, &log), 2) << log;
  EXPECT_NE(log.find("quote"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "pwned"));
  EXPECT_THROW(read_mesh(testing::geo_path("cube_sphere.geo"), {.set_numbers = {{"h;", 0.1}}}),
               InputError);
}

}  // namespace
}  // namespace cvtmesh
