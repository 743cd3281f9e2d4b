// cvtmesh mesh IN -o OUT: the paper's "Init" mesh — Gmsh's boundary mesh and constrained
// Delaunay volume mesh with every optimizer off (average quality, slivers present).
#include <iostream>
#include <memory>

#include "convert/cli_common.h"

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
  commands().push_back({c, [in, out] {
                          const MeshData d = read_mesh(in->path, init_read_options(*in));
                          write_mesh(d, out->path, out->to_write_options(d, in->path));
                          info() << "cvtmesh: wrote " << out->path << "\n";
                          return 0;
                        }});
}

}  // namespace cvtmesh::cli
