// cvtmesh: the command-line front end. Parses arguments, calls core/, prints. Nothing else.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <string>

#include "convert/commands.h"
#include "core/util/error.h"

int main(int argc, char** argv) {
  CLI::App app{"cvtmesh " CVTMESH_VERSION
               " - CVT (centroidal Voronoi) mesh optimization for Gmsh meshes (Du & Wang)"};
  app.set_version_flag("--version", "cvtmesh " CVTMESH_VERSION);
  app.require_subcommand(1);
  cvtmesh::cli::register_commands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return cvtmesh::cli::run_selected(app);
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
