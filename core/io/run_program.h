// Runs another program as a child process (no shell) and waits for it: what cvtmesh uses to call a
// helper from Debian it depends on (rsvg-convert for the PNG histograms). Standard input is
// /dev/null, standard output is discarded and the first bytes of standard error are returned.
#pragma once
#include <string>
#include <vector>

namespace cvtmesh {

// The absolute path of `name` found in $PATH (or `name` itself if it holds a '/' and is an
// executable file); "" if there is none.
std::string find_program(const std::string& name);

struct ProgramRun {
  int exit_code = -1;        // -1: could not be started, or killed by a signal
  std::string error_output;  // its standard error (at most 4 kB), or why it could not start
};

// argv[0] is the program's path. Never throws for a failing child: the caller reads the result.
ProgramRun run_program(const std::vector<std::string>& argv);

}  // namespace cvtmesh
