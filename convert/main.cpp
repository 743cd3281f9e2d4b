// cvtmesh: the command-line front end. Parses arguments, calls core/, prints. Nothing else.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <new>
#include <string>

#include "convert/cli_common.h"
#include "convert/commands.h"
#include "convert/limits.h"
#include "core/util/error.h"

int main(int argc, char** argv) {
  CLI::App app{"cvtmesh " CVTMESH_VERSION
               " - CVT (centroidal Voronoi) mesh optimization for Gmsh meshes (Du & Wang)"};
  app.set_version_flag("--version", "cvtmesh " CVTMESH_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // subcommands inherit it: --max-memory / --time-limit also after them
  app.footer(
      "Exit codes: 0 ok, 1 usage error, 2 bad input (unreadable file, refused option value), 3 "
      "cannot write the output, 4 internal error, 5 `check` found problems, 6 `optimize "
      "--strict` fell short.");
  cvtmesh::cli::register_commands(app);
  cvtmesh::cli::Limits limits;
  cvtmesh::cli::add_limit_options(app, limits);
  cvtmesh::cli::add_global_options(app);
  using namespace cvtmesh::cli;
  try {
    app.parse(argc, argv);
    apply_limits(limits);
    apply_global_options();
  } catch (const CLI::ParseError& e) {
    // --help / --version exit 0; every other parse error is a usage error (CLI11's own codes,
    // 105 to 109, are not ours).
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }
  try {
    return run_selected(app);
  } catch (const CLI::Error& e) {
    // A value CLI11 accepted but a subcommand could not use (e.g. --set without '=').
    std::cerr << "cvtmesh: error: " << e.what() << "\n";
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    std::cerr << "cvtmesh: error: out of memory"
              << (limits.max_memory_mb > 0 ? " (the --max-memory limit was reached)" : "")
              << "; no output written\n";
    return kExitBadInput;
  } catch (const cvtmesh::InputError& e) {
    // Under --max-memory a reader's library may report the failed allocation its own way (an
    // OpenCASCADE exception "Standard_MMgrRaw::Allocate(): malloc failed" through Gmsh): say it.
    const std::string what = e.what();
    const bool allocation = what.find("malloc failed") != std::string::npos ||
                            what.find("out of memory") != std::string::npos ||
                            what.find("bad_alloc") != std::string::npos;
    std::cerr << "cvtmesh: error: " << what
              << (limits.max_memory_mb > 0 && allocation &&
                          what.find("out of memory") == std::string::npos
                      ? " (out of memory: the --max-memory limit was reached)"
                      : "")
              << "\n";
    return kExitBadInput;
  } catch (const cvtmesh::OutputError& e) {
    std::cerr << "cvtmesh: error: " << e.what() << "\n";
    return kExitCannotWrite;
  } catch (const cvtmesh::InvariantError& e) {
    std::cerr << "cvtmesh: internal error (mesh invariant violated, nothing written): " << e.what()
              << "\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "cvtmesh: internal error: " << e.what() << "\n";
    return kExitInternal;
  }
}
