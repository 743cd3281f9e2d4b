// Limits a service needs when it converts files from others (docs/reliability.md, Security):
// --max-memory MB (the address space, RLIMIT_AS: an allocation past it fails, reported as exit 2)
// and --time-limit S (wall clock: at the deadline every uncommitted output is removed and the
// process exits 2 with a message). Both are options of the main app, given before or after the
// subcommand.
#pragma once
#include <CLI/CLI.hpp>

namespace cvtmesh::cli {

struct Limits {
  double max_memory_mb = 0;  // 0: none
  double time_limit_s = 0;   // 0: none
};

void add_limit_options(CLI::App& app, Limits& limits);

// Applies the limits to this process (the memory limit at once, the time limit by a watchdog
// thread). Throws CLI::ValidationError for a limit it cannot set.
void apply_limits(const Limits& limits);

// Seconds left before the time limit's deadline (+inf without a limit): the optional work of a
// run (optimize's interior refinement of a coarse model) is not started when it would not fit.
double seconds_left();

}  // namespace cvtmesh::cli
