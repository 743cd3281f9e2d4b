// The CLI subcommands: each registers its options on the app and runs when selected.
#pragma once
#include <CLI/CLI.hpp>

namespace cvtmesh::cli {

void register_commands(CLI::App& app);
int run_selected(CLI::App& app);

}  // namespace cvtmesh::cli
