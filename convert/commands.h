// The CLI subcommands: each registers its options on the app and runs when selected.
#pragma once
#include <CLI/CLI.hpp>

namespace cvtmesh::cli {

void register_commands(CLI::App& app);
int run_selected(CLI::App& app);
// The whole command line: parse, run the selected subcommand, map errors to the exit codes.
int run_cli(int argc, char** argv);

}  // namespace cvtmesh::cli
