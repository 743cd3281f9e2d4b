// The whole bad-input corpus (tests/bad_input/corpus.h, plus the committed regression files in
// tests/bad_input/files/) through `cvtmesh convert` and `cvtmesh optimize`: every case gives a
// non-zero exit below 128 (no crash, no signal), exactly one line naming the file and the
// problem, and no output nor temporary file in the output directory.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/bad_input/corpus.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

namespace fs = std::filesystem;
using testing::BadInputCase;

std::string q(const std::string& s) {
  return "'" + s + "'";
}

std::vector<std::string> listing(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    names.push_back(fs::relative(e.path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

// Runs `command` ("convert" or "optimize") on the case in a fresh directory and checks the
// refusal. Returns false if the case does not apply (unreadable file when running as root and
// the CLI cannot be run as an unprivileged user).
bool expect_refused(const BadInputCase& c, const std::string& command) {
  const std::string dir = testing::temp_dir();
  testing::write_bad_input_case(c, dir);
  std::string as_user;
  if (c.kind == BadInputCase::Kind::kUnreadable &&
      access((dir + "/" + c.name).c_str(), R_OK) == 0) {  // root reads anything
    as_user = testing::unprivileged_prefix();
    if (as_user.empty()) return false;
    fs::permissions(dir, fs::perms::all);  // nobody may enter (and write) the directory
  }
  const std::vector<std::string> before = listing(dir);
  const std::string args =
      command == "convert" ? q(c.name) + " " + q(c.output) : q(c.name) + " -o " + q(c.output);
  std::string log;
  const int rc = testing::run("cd " + q(dir) + " && " + as_user + testing::cli_path() + " " +
                                  command + " " + args + " " + c.extra,
                              &log);
  EXPECT_GT(rc, 0) << log;
  EXPECT_LT(rc, 128) << "crashed (signal or abort): " << log;
  std::string line = log;
  while (!line.empty() && line.back() == '\n') line.pop_back();
  EXPECT_FALSE(line.empty()) << "no message";
  EXPECT_EQ(line.find('\n'), std::string::npos) << "more than one line:\n" << log;
  const bool about_output = c.message.rfind("out:", 0) == 0;
  const std::string named = about_output ? c.output : c.name;
  EXPECT_NE(line.find(named), std::string::npos) << "does not name '" << named << "': " << line;
  const std::string words = about_output ? c.message.substr(4) : c.message;
  EXPECT_NE(line.find(words), std::string::npos) << "expected '" << words << "' in: " << line;
  // Nothing was added to (or removed from) the directory: no output, no temporary file.
  EXPECT_EQ(listing(dir), before) << "files changed by a refused run";
  fs::permissions(dir, fs::perms::owner_all, fs::perm_options::add);
  if (c.kind == BadInputCase::Kind::kUnreadable)
    fs::permissions(dir + "/" + c.name, fs::perms::owner_all, fs::perm_options::add);
  return true;
}

TEST(BadInputCorpus, HasAtLeastThirtyDistinctCases) {
  const auto corpus = testing::bad_input_corpus();
  EXPECT_GE(corpus.size(), 30u);
  std::vector<std::string> keys;
  for (const auto& c : corpus) keys.push_back(c.name + "|" + c.output + "|" + c.extra);
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(std::adjacent_find(keys.begin(), keys.end()), keys.end()) << "duplicate case";
}

// Every case applies unless running as root without a way to run the CLI as nobody.
void expect_all_applied(int skipped) {
  if (geteuid() != 0 || !testing::unprivileged_prefix().empty()) EXPECT_EQ(skipped, 0);
}

TEST(BadInputCorpus, ConvertRefusesEachCaseCleanly) {
  int skipped = 0;
  for (const BadInputCase& c : testing::bad_input_corpus()) {
    SCOPED_TRACE("convert " + c.name + " " + c.output + " " + c.extra);
    skipped += !expect_refused(c, "convert");
  }
  expect_all_applied(skipped);
}

TEST(BadInputCorpus, OptimizeRefusesEachCaseCleanly) {
  int skipped = 0;
  for (const BadInputCase& c : testing::bad_input_corpus()) {
    if (c.extra == "--quality" && c.output == "out.mesh") continue;  // convert-only option
    SCOPED_TRACE("optimize " + c.name + " -o " + c.output + " " + c.extra);
    skipped += !expect_refused(c, "optimize");
  }
  expect_all_applied(skipped);
}

// Inputs committed as files (tests/bad_input/files/README.md): refused cleanly, message naming
// the file. Files are named FORMAT_DEFECT.EXT; files sharing a stem form one case (a TetGen
// .node/.ele set), run on the one whose extension is the FORMAT prefix (the defective one).
TEST(BadInputCorpus, CommittedRegressionFilesAreRefusedCleanly) {
  const fs::path dir = testing::bad_input_files_dir();
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && e.path().filename() != "README.md") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  int n = 0;
  for (const fs::path& f : files) {
    const std::string stem = f.stem().string();
    const std::string input_ext = "." + stem.substr(0, stem.find('_'));
    if (f.extension() != input_ext && fs::exists(dir / (stem + input_ext)))
      continue;  // a companion of that input
    BadInputCase c;
    c.name = f.filename().string();
    c.files = {{c.name, slurp(f)}};
    for (const fs::path& other : files)
      if (other != f && other.stem() == f.stem())
        c.files.push_back({other.filename().string(), slurp(other)});
    if (c.name.find("truncated") != std::string::npos) c.message = "truncated";
    SCOPED_TRACE(c.name);
    expect_refused(c, "convert");
    ++n;
  }
  // A loop over an empty folder would pass without testing anything.
  ASSERT_GE(n, 1) << "no regression file in " << dir;
  RecordProperty("files", n);
}

}  // namespace
}  // namespace cvtmesh
