// End-to-end runs of the cvtmesh CLI: the quality table, conversions, and bad input. Every bad
// input gives a non-zero exit, one line naming the file, and no output (nor temporary) file.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "tests/io/gmsh_dump.h"
#include "tests/bad_input/corpus.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

namespace fs = std::filesystem;
using testing::run;

std::string cli() {
  return testing::cli_path();
}
std::string q(const std::string& s) {
  return "'" + s + "'";
}

void spit(const std::string& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}
std::string slurp(const std::string& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Rows of the text table: label -> value (first column).
std::map<std::string, double> table_rows(const std::string& out) {
  std::map<std::string, double> rows;
  std::istringstream in(out);
  std::string line;
  const std::regex row(R"(^(.*\S)\s{2,}(-?[0-9.]+)\s*$)");
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, row)) rows[m[1]] = std::stod(m[2]);
  }
  return rows;
}

TEST(Cli, StatsPrintsTheTable6Rows) {
  std::string out;
  ASSERT_EQ(run(cli() + " stats " + q(testing::geo_path("cube_sphere.geo")), &out), 0) << out;
  const auto rows = table_rows(out);
  for (const char* r :
       {"number of elements", "0.7 < Q <= 1.0", "0.5 < Q <= 0.7", "0.3 < Q <= 0.5",
        "0.0 < Q <= 0.3", "Q_min", "bad elements (%)", "good elements (%)", "average quality"})
    ASSERT_TRUE(rows.count(r)) << "missing row '" << r << "' in:\n" << out;
  const double n = rows.at("number of elements");
  const double b1 = rows.at("0.7 < Q <= 1.0"), b2 = rows.at("0.5 < Q <= 0.7"),
               b3 = rows.at("0.3 < Q <= 0.5"), b4 = rows.at("0.0 < Q <= 0.3");
  // A valid mesh: every element in one of the four bins.
  EXPECT_EQ(b1 + b2 + b3 + b4, n);
  EXPECT_NEAR(rows.at("good elements (%)"), 100 * (b1 + b2) / n, 0.006);
  EXPECT_GT(rows.at("Q_min"), 0);
  EXPECT_LE(rows.at("Q_min"), rows.at("average quality"));
  EXPECT_LE(rows.at("average quality"), 1);
  // The paper's example is meshed with roughly 24-26k tets by default.
  EXPECT_GT(n, 20000);
  EXPECT_LT(n, 30000);
}

TEST(Cli, ConvertWithQualityGivesAMshWithThreeViews) {
  const std::string dir = testing::temp_dir();
  const std::string out = dir + "/cs.msh";
  std::string log;
  ASSERT_EQ(run(cli() + " convert " + q(testing::geo_path("cube_sphere.geo")) + " " + q(out) +
                    " --quality --set h=0.12",
                &log),
            0)
      << log;
  std::string stats;
  ASSERT_EQ(run(cli() + " stats " + q(out), &stats), 0) << stats;
  const auto rows = table_rows(stats);
  const testing::GmshDump g = testing::gmsh_dump(out);
  ASSERT_EQ(g.views.size(), 3u);
  ASSERT_TRUE(g.views.count("Q (Du-Wang)"));
  const auto& qv = g.views.at("Q (Du-Wang)");
  // One value per written element, NaN on those that are not tets (docs/cli.md).
  EXPECT_EQ(qv.size(), g.elements.size());
  double qmin = 1e9, qsum = 0;
  long nb = 0;
  for (const auto& [tag, v] : qv) {
    if (std::isnan(v)) continue;
    qmin = std::min(qmin, v);
    qsum += v;
    ++nb;
  }
  EXPECT_EQ(static_cast<double>(nb), rows.at("number of elements"));
  // The view holds the values `stats` summarizes (printed to 4 decimals).
  EXPECT_NEAR(qmin, rows.at("Q_min"), 5e-5);
  EXPECT_NEAR(qsum / nb, rows.at("average quality"), 5e-5);
  // The mesh and its companion .opt (Gmsh merges it: the Q view alone), nothing else.
  EXPECT_TRUE(fs::exists(out + ".opt"));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 2);
}

TEST(Cli, ConvertsToEveryOwnFormat) {
  const std::string dir = testing::temp_dir();
  const std::string msh = dir + "/in.msh";
  ASSERT_EQ(run(cli() + " convert " + q(testing::geo_path("cube_sphere.geo")) + " " + q(msh) +
                " --set h=0.25 --set h_ball=0.15"),
            0);
  for (const char* ext : {".vtk", ".vtu", ".node", ".mesh", ".off", ".obj", ".ply", ".stl"}) {
    const std::string out = dir + "/out" + ext;
    std::string log;
    EXPECT_EQ(run(cli() + " convert " + q(msh) + " " + q(out), &log), 0) << ext << ": " << log;
    EXPECT_TRUE(fs::exists(out)) << ext;
    if (std::string(ext) != ".stl" && std::string(ext) != ".off" && std::string(ext) != ".obj" &&
        std::string(ext) != ".ply") {
      // Meshes read back with the same number of elements.
      std::string a, b;
      ASSERT_EQ(run(cli() + " stats " + q(out), &a), 0) << a;
      ASSERT_EQ(run(cli() + " stats " + q(msh), &b), 0) << b;
      EXPECT_EQ(table_rows(a).at("number of elements"), table_rows(b).at("number of elements"));
    }
  }
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find("cvtmesh-tmp"), std::string::npos)
        << "stray temporary " << e.path();
}

// ---------------------------------------------------------------------------------------------
// Bad input

// A valid one-tet .msh (shared with the bad-input corpus).
const std::string kTet = testing::good_tet_msh();

struct BadCase {
  std::string name;     // input file name (in the test directory)
  std::string content;  // written unless empty and `make` is set
  std::string message;  // expected in the error line
  std::string output = "out.msh";
  std::string extra;  // extra arguments
};

void expect_refused(const std::string& dir, const BadCase& c, const std::string& as_user = "") {
  SCOPED_TRACE(c.name);
  const std::string in = dir + "/" + c.name;
  const std::string out = dir + "/" + c.output;
  std::string log;
  const int rc = run("cd " + q(dir) + " && " + as_user + cli() + " convert " + q(c.name) + " " +
                         q(c.output) + " " + c.extra,
                     &log);
  EXPECT_NE(rc, 0) << log;
  EXPECT_FALSE(rc == 128) << "crashed: " << log;
  // One line, naming the file (input, or output for output problems), with the expected words.
  std::string trimmed = log;
  while (!trimmed.empty() && trimmed.back() == '\n') trimmed.pop_back();
  EXPECT_EQ(trimmed.find('\n'), std::string::npos) << "more than one line:\n" << log;
  const std::string& named = c.message.rfind("out:", 0) == 0 ? c.output : c.name;
  EXPECT_NE(log.find(named), std::string::npos) << "does not name '" << named << "': " << log;
  const std::string words = c.message.rfind("out:", 0) == 0 ? c.message.substr(4) : c.message;
  EXPECT_NE(log.find(words), std::string::npos) << "expected '" << words << "' in: " << log;
  EXPECT_FALSE(fs::exists(out) && c.output != c.name) << "an output file was left: " << out;
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_EQ(e.path().filename().string().find("cvtmesh-tmp"), std::string::npos)
        << "stray temporary " << e.path();
  (void)in;
}

// The bad-input cases themselves are in tests/bad_input/ (the corpus, run through the CLI).

TEST(CliBadInput, OutputIntoAReadOnlyDirectory) {
  const std::string dir = testing::temp_dir();
  spit(dir + "/in.msh", kTet);
  fs::create_directory(dir + "/ro");
  chmod((dir + "/ro").c_str(), 0555);
  std::string as_user;
  if (access((dir + "/ro").c_str(), W_OK) == 0) {  // root writes anywhere: run as nobody
    as_user = testing::unprivileged_prefix();
    if (as_user.empty())
      GTEST_SKIP() << "running as root, and the CLI cannot be run as user nobody from here";
    fs::permissions(dir, fs::perms::all);
  }
  expect_refused(dir, {"in.msh", "", "out:not writable", "ro/out.msh"}, as_user);
  EXPECT_TRUE(fs::is_empty(dir + "/ro"));
}

// Gmsh sizes its arrays by the declared counts (fuzz_msh finding): 4e11 nodes declared in a
// 200-byte file. Not in the bad-input corpus, which also runs under ASan: ASan aborts on such an
// allocation instead of throwing std::bad_alloc.
TEST(CliBadInput, AHugeDeclaredNodeCountIsRefusedCleanly) {
  const std::string dir = testing::temp_dir();
  std::string huge = kTet;
  const std::string from = "$Nodes\n1 4 1 4\n";
  ASSERT_NE(huge.find(from), std::string::npos);
  huge.replace(huge.find(from), from.size(), "$Nodes\n1 400000000000 1 4\n");
  spit(dir + "/huge.msh", huge);
  expect_refused(dir, {"huge.msh", "", "declares more data than it can hold"});
}

TEST(CliBadInput, InputIsNotOverwrittenWithoutInPlace) {
  const std::string dir = testing::temp_dir();
  spit(dir + "/same.msh", kTet);
  const std::string before = slurp(dir + "/same.msh");
  for (const std::string out : {"same.msh", "./same.msh"}) {
    std::string log;
    EXPECT_NE(run("cd " + q(dir) + " && " + cli() + " convert same.msh " + out, &log), 0);
    EXPECT_NE(log.find("--in-place"), std::string::npos) << log;
    EXPECT_EQ(slurp(dir + "/same.msh"), before) << "the input was changed";
  }
  // With --in-place it is replaced (by an equivalent mesh).
  std::string log;
  EXPECT_EQ(run("cd " + q(dir) + " && " + cli() + " convert same.msh same.msh --in-place", &log), 0)
      << log;
  EXPECT_EQ(run(cli() + " stats " + q(dir + "/same.msh"), &log), 0) << log;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace cvtmesh
