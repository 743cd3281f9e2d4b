// The bad-input corpus (issue 6): inputs and output locations the CLI must refuse with one line
// naming the file and the problem, a non-zero exit below 128 (no crash), and no output or
// temporary file left behind. Cases are generated here (small, readable edits of one good tet);
// crashers found by the fuzzers (fuzz/) are committed as files under tests/bad_input/files/.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace cvtmesh::testing {

struct BadInputCase {
  enum class Kind { kFile, kMissing, kDirectory, kUnreadable };
  std::string name;  // the input, relative to the case directory
  // Files written into the case directory (name, content); the input is usually the only one.
  std::vector<std::pair<std::string, std::string>> files;
  // Words expected in the error line; "out:..." means the line names the output, not the input.
  std::string message;
  std::string output = "out.msh";  // relative to the case directory
  std::string extra;               // extra CLI arguments
  Kind kind = Kind::kFile;
};

// A valid single-tet mesh in each format the corpus edits (Gmsh 4.1 ASCII .msh, Medit, TetGen
// .node/.ele, legacy VTK).
std::string good_tet_msh();

// Every generated case (at least 30), covering .msh, .geo, .stl/.off, Medit, TetGen, VTK/VTU,
// paths that are directories or unreadable, and bad output locations.
std::vector<BadInputCase> bad_input_corpus();

// Creates the case's files (or directory, or unreadable file) in dir.
void write_bad_input_case(const BadInputCase& c, const std::string& dir);

// The directory of committed regression inputs (fuzzer crashers): tests/bad_input/files.
std::string bad_input_files_dir();

}  // namespace cvtmesh::testing
