// cvtmesh-onelab: the optimizer as a ONELAB client of an unmodified Gmsh. Register it with
//   gmsh model.geo -setstring Solver.Name0 cvtmesh -setstring Solver.Executable0
//   /path/cvtmesh-onelab
// (or Solver.Name0/Solver.Executable0 in an option file), pick Modules > Solver > cvtmesh in the
// tree, then press Run. Gmsh launches `cvtmesh-onelab -onelab NAME SOCKET` for each action: on
// initialize/check the "Mesh optimization (CVT)" inputs are (re)defined in Gmsh's tree; on compute
// the mesh Gmsh saved (Gmsh/MshFileName) is optimized, written next to it as <name>_cvt.msh with
// per-element quality, and shown in the GUI in place of the model (the next Run re-meshes the
// model and starts again). Thin: the work is in core/.
#include <algorithm>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "plugin/gmsh_inprocess.h"
#include "core/quality/quality_fields.h"
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

// <dir>/<stem>_cvt.msh for <dir>/<stem>.<ext>; a file already named *_cvt.msh (a project opened
// from an earlier result) is its own output rather than piling up suffixes.
std::string output_path(const std::string& input) {
  const auto slash = input.find_last_of('/');
  const auto dot = input.find_last_of('.');
  std::string stem = (dot != std::string::npos && (slash == std::string::npos || dot > slash))
                         ? input.substr(0, dot)
                         : input;
  const std::string suffix = "_cvt";
  if (stem.size() < suffix.size() ||
      stem.compare(stem.size() - suffix.size(), suffix.size(), suffix))
    stem += suffix;
  return stem + ".msh";
}

// .geo-language text that shows the result in the GUI in place of the model: removes the quality
// views of an earlier run (by name), replaces the model by the result ("Delete Model; Merge" --
// the project file stays the model's, so the next Run re-meshes it), and shows the new Q view
// like cvtmesh-gui does: alone, over [0, 1], in 3D cut by the plane x = x_mid (whole elements).
std::string load_script(const MeshData& data, const std::string& path, std::size_t nb_views) {
  // One statement per line: Gmsh runs a For loop by rewinding its input to the line after For.
  std::vector<std::string> names;
  for (int d : {2, 3})
    for (const auto& n : quality_view_names(d))
      if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  std::string ours;
  for (const auto& n : names)
    ours += std::string(ours.empty() ? "" : " || ") + "(StrCmp(Sprintf(View[cvt_v].Name), \"" + n +
            "\") == 0)";
  std::string s = "For cvt_v In {PostProcessing.NbViews - 1 : 0 : -1}\nIf (" + ours +
                  ")\nDelete View[cvt_v];\nEndIf\nEndFor\n";
  s += "Delete Model;\nMerge \"" + path + "\";\n";
  if (nb_views == 0) return s;
  s += "cvt_q = PostProcessing.NbViews - " + std::to_string(nb_views) + ";\n";
  s += "View[cvt_q].RangeType = 2;\nView[cvt_q].CustomMin = 0;\nView[cvt_q].CustomMax = 1;\n";
  for (std::size_t v = 1; v < nb_views; ++v)
    s += "View[cvt_q + " + std::to_string(v) + "].Visible = 0;\n";
  if (data.dim == 3 && data.tet.nb_vertices() > 0) {
    double lo = data.tet.point(0)[0], hi = lo;
    for (int v = 0; v < data.tet.nb_vertices(); ++v) {
      lo = std::min(lo, data.tet.point(v)[0]);
      hi = std::max(hi, data.tet.point(v)[0]);
    }
    s += "General.Clip0A = -1;\nGeneral.Clip0B = 0;\nGeneral.Clip0C = 0;\nGeneral.Clip0D = " +
         std::to_string(0.5 * (lo + hi)) +
         ";\nGeneral.ClipWholeElements = 1;\nView[cvt_q].Clip = 1;\nMesh.Clip = 1;\n";
  }
  return s;
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
  tree.info("cvtmesh: wrote " + out + "; showing it in place of the model");
  tree.parse_string(load_script(data, out, w.fields.size()));
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
    // The method list depends on the model's dimension: Gmsh publishes it; else what a previous
    // compute found; else 3D.
    int dim = static_cast<int>(tree->number("Gmsh/Model dimension").value_or(0));
    if (dim != 2 && dim != 3) dim = plugin::panel_dim(*tree);
    plugin::define_panel(*tree, dim == 2 ? 2 : 3);
    if (action == "compute") return compute(*tree);
    return 0;
  } catch (const std::exception& e) {
    tree->error(std::string("cvtmesh: ") + e.what());
    return 1;
  }
}
