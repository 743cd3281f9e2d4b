// cvtmesh's command line, shared by its two mains (convert/main.cpp, convert/mpi/main_mpi.cpp):
// parses arguments, calls core/, prints. Nothing else.
#include <CLI/CLI.hpp>
#include <malloc.h>

#include <cstdio>
#include <iostream>
#include <limits>
#include <new>
#include <string>

#include "convert/cli_common.h"
#include "convert/commands.h"
#include "convert/limits.h"
#include "core/util/error.h"

namespace cvtmesh::cli {

int run_cli(int argc, char** argv) {
  // Freed memory kept for the next allocation instead of given back: glibc serves arrays above
  // 32 MB from fresh mmaps, each page of which the kernel zeroes on first touch, so at ~10M tets
  // (arrays of 40-400 MB made and freed every iteration) a run spent ~58 s of CPU in page faults.
  // `cvtmesh -v optimize` of the 9.15M-tet cube_sphere Init (docs/benchmarks.md, stop 28), with
  // the same settings through GLIBC_TUNABLES (mmap_max=0, trim threshold 64 GB): 530.7 -> 482.1 s
  // in optimize, system time 57.7 -> 23.5 s, peak RSS 7.67 GB (6.55 GB without). At ~1M tets
  // (c1m) the same time (glibc's own threshold adapts below 32 MB) and peak RSS 823 -> 849 MB.
  mallopt(M_MMAP_MAX, 0);
  mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());  // 2 GB free at the top
  CLI::App app{"cvtmesh " CVTMESH_VERSION
               " - CVT (centroidal Voronoi) mesh optimization for Gmsh meshes (Du & Wang)"};
  app.set_version_flag("--version", "cvtmesh " CVTMESH_VERSION);
  app.require_subcommand(1);
  app.fallthrough();  // subcommands inherit it: --max-memory / --time-limit also after them
  app.footer(
      "Exit codes: 0 ok, 1 usage error, 2 bad input (unreadable file, refused option value), 3 "
      "cannot write the output, 4 internal error, 5 `check` found problems, 6 `optimize "
      "--strict` fell short.");
  register_commands(app);
  Limits limits;
  add_limit_options(app, limits);
  add_global_options(app);
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

}  // namespace cvtmesh::cli
