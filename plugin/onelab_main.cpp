// cvtmesh-onelab: the optimizer as a ONELAB client of an unmodified Gmsh. Register it with
//   gmsh model.geo -setstring Solver.Name0 cvtmesh -setstring Solver.Executable0 /path/cvtmesh-onelab
// (or Solver.Name0/Solver.Executable0 in an option file), pick Modules > Solver > cvtmesh in the
// tree, then press Run. Gmsh launches `cvtmesh-onelab -onelab NAME SOCKET` for each action: on
// initialize/check the "Mesh optimization (CVT)" inputs are (re)defined in Gmsh's tree; on compute
// the mesh Gmsh saved (Gmsh/MshFileName) is optimized, written next to it as <name>_cvt.msh with
// per-element quality, and opened in the GUI in place of the model. Thin: the work is in core/.
#include <exception>
#include <iostream>
#include <string>

#include "core/io/read_mesh.h"
#include "core/io/write_mesh.h"
#include "core/pipeline/optimize.h"
#include "plugin/onelab_remote.h"
#include "plugin/panel.h"

namespace {

using namespace cvtmesh;

const char* const kUsage =
    "usage: cvtmesh-onelab -onelab NAME SOCKET   (launched by Gmsh, not by hand)\n"
    "Register it in Gmsh as a ONELAB solver:\n"
    "  gmsh model.geo -setstring Solver.Name0 cvtmesh -setstring Solver.Executable0 PATH\n"
    "then select Modules > Solver > cvtmesh in the tree and press Run. See docs/gmsh.md.\n";

// <dir>/<stem>_cvt.msh for <dir>/<stem>.<ext>; a file already named *_cvt.msh is its own output,
// so that running again optimizes the loaded result further instead of piling up suffixes.
std::string output_path(const std::string& input) {
  const auto slash = input.find_last_of('/');
  const auto dot = input.find_last_of('.');
  std::string stem = (dot != std::string::npos && (slash == std::string::npos || dot > slash))
                         ? input.substr(0, dot)
                         : input;
  const std::string suffix = "_cvt";
  if (stem.size() < suffix.size() || stem.compare(stem.size() - suffix.size(), suffix.size(), suffix))
    stem += suffix;
  return stem + ".msh";
}

int compute(plugin::RemoteOnelab& tree) {
  const std::string in = tree.string("Gmsh/MshFileName").value_or("");
  if (in.empty()) {
    tree.error("cvtmesh: Gmsh did not give a mesh file (Gmsh/MshFileName); mesh the model first");
    return 1;
  }
  tree.progress("cvtmesh: reading " + in);
  MeshData data = read_mesh(in);
  if (data.dim != plugin::panel_dim(tree)) plugin::define_panel(tree, data.dim);
  GmshOptimizeOptions o = plugin::read_panel(tree);
  const int max_it = o.optimize.max_iterations;
  o.optimize.progress = [&](const OptimizeProgress& p) {
    tree.progress(plugin::progress_text(p, max_it));
  };
  tree.info("cvtmesh: optimizing " + in + " with " + o.optimize.method + "...");
  GmshOptimizeResult r;
  r.result = optimize(data, o.optimize);
  r.method = o.optimize.method;
  r.dim = data.dim;

  const std::string out = output_path(in);
  WriteOptions w;
  if (o.quality_views) w.fields = quality_fields(data);
  w.policy.force = true;  // our own output, replaced on every run
  w.policy.input_path = in;
  w.policy.in_place = true;  // running again on a loaded result rewrites it
  write_mesh(data, out, w);
  plugin::show_results(tree, r);
  tree.info(plugin::summary(r));
  tree.info("cvtmesh: wrote " + out + "; opening it in place of the model");
  tree.open_project(out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::unique_ptr<plugin::RemoteOnelab> tree;
  try {
    tree = plugin::RemoteOnelab::connect(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << "cvtmesh-onelab: " << e.what() << "\n";
    return 1;
  }
  if (!tree) {
    std::cerr << kUsage;
    return 2;
  }
  try {
    const std::string action = tree->action();
    const int dim = plugin::panel_dim(*tree);
    plugin::define_panel(*tree, dim ? dim : 3);
    if (action == "compute") return compute(*tree);
    return 0;
  } catch (const std::exception& e) {
    tree->error(std::string("cvtmesh: ") + e.what());
    return 1;
  }
}
