// cvtmesh mesh IN -o OUT: the paper's "Init" mesh — Gmsh's boundary mesh and constrained
// Delaunay volume mesh with every optimizer off (average quality, slivers present).
// --gmsh-optimize: the mesh `optimize` reads from IN (Gmsh's meshing options as they are),
// then Gmsh's own tet optimizer on it (optimize(""), compare's "Gmsh optimize" baseline), its time
// printed: the corpus table's Gmsh column.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "bench/baselines/gmsh_optimizer.h"
#include "convert/cli_common.h"
#include "core/util/error.h"

namespace cvtmesh::cli {

ReadOptions init_read_options(const InputOpts& in) {
  ReadOptions r = in.to_read_options();
  r.gmsh_optimize = false;
  return r;
}

void register_mesh(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  auto out = std::make_shared<OutputOpts>();
  CLI::App* c = app.add_subcommand(
      "mesh",
      "mesh a model with Gmsh, optimizers off: the initial mesh of the paper's tables (\"Init\")");
  add_input(c, *in);
  c->add_option("-o,--output", out->path, "output file (format by extension)")->required();
  add_output_flags(c, *out);
  auto gmsh_optimize = std::make_shared<bool>(false);
  c->add_flag("--gmsh-optimize", *gmsh_optimize,
              "then run Gmsh's tet optimizer on the mesh (optimize(\"\"), compare's \"Gmsh "
              "optimize\" baseline) and print its time");
  commands().push_back(
      {c, [in, out, gmsh_optimize] {
         // With --gmsh-optimize: the mesh optimize reads (Gmsh's meshing
         // options as they are), then Gmsh's optimizer on it.
         MeshData d =
             read_mesh(in->path, *gmsh_optimize ? in->to_read_options() : init_read_options(*in));
         if (*gmsh_optimize) {
           if (d.dim != 3) throw InputError("--gmsh-optimize: needs a 3D tetrahedral mesh");
           const auto t0 = std::chrono::steady_clock::now();
           gmsh_optimize_mesh(d, "", 1);
           std::fprintf(
               stderr, "cvtmesh: Gmsh optimize: %.3f s\n",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
         }
         const WriteReport written = write_mesh(d, out->path, out->to_write_options(d, in->path));
         for (const auto& note : written.notes) info() << "cvtmesh: note: " << note << "\n";
         info() << "cvtmesh: wrote " << out->path << "\n";
         return 0;
       }});
}

}  // namespace cvtmesh::cli
