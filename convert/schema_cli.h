// The CLI flags of the option schema (core/pipeline/option_schema.h), shared by the cvtmesh
// subcommands and the reproduction drivers of bench/.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "core/pipeline/optimize.h"

namespace cvtmesh::cli {

// Adds one flag per option of the schema shown on the CLI (its flag, and describe()'s help with
// the default and range) bound to o's field, except the options named in `except`. No range
// check here: optimize() validates, so every front end refuses a value with the same message.
void add_schema_options(CLI::App* c, OptimizeOptions& o,
                        const std::vector<std::string>& except = {});

}  // namespace cvtmesh::cli
