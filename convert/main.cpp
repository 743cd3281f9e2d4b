// cvtmesh: the command-line front end. Parses arguments, calls core/, prints. Nothing else.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <new>
#include <string>

#include "convert/commands.h"
#include "convert/limits.h"
#include "core/util/error.h"

int main(int argc, char** argv) {
  CLI::App app{"cvtmesh " CVTMESH_VERSION
               " - CVT (centroidal Voronoi) mesh optimization for Gmsh meshes (Du & Wang)"};
  app.set_version_flag("--version", "cvtmesh " CVTMESH_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // subcommands inherit it: --max-memory / --time-limit also after them
  cvtmesh::cli::register_commands(app);
  cvtmesh::cli::Limits limits;
  cvtmesh::cli::add_limit_options(app, limits);
  try {
    app.parse(argc, argv);
    cvtmesh::cli::apply_limits(limits);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return cvtmesh::cli::run_selected(app);
  } catch (const std::bad_alloc&) {
    std::cerr << "cvtmesh: error: out of memory"
              << (limits.max_memory_mb > 0 ? " (the --max-memory limit was reached)" : "")
              << "; no output written\n";
    return 2;
  } catch (const cvtmesh::InputError& e) {
    std::cerr << "cvtmesh: error: " << e.what() << "\n";
    return 2;
  } catch (const cvtmesh::OutputError& e) {
    std::cerr << "cvtmesh: error: " << e.what() << "\n";
    return 3;
  } catch (const cvtmesh::InvariantError& e) {
    std::cerr << "cvtmesh: internal error (mesh invariant violated, nothing written): " << e.what()
              << "\n";
    return 4;
  } catch (const std::exception& e) {
    std::cerr << "cvtmesh: error: " << e.what() << "\n";
    return 1;
  }
}
