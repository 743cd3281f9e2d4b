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
#include <array>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "plugin/gmsh_inprocess.h"
#include "core/mesh/check_surface_mesh.h"
#include "core/io/quality_view_geo.h"
#include "core/quality/quality_fields.h"
#include "core/quality/quality_histogram.h"
#include "core/quality/quality_stats.h"
#include "core/io/read_mesh.h"
#include "core/io/write_mesh.h"
#include "core/pipeline/optimize.h"
#include "core/util/wait_policy.h"
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

// .geo-language text: a For loop over the views whose name is one of `names`, running `body`
// once for each (cvt_v: the view's index; one condition, so a body that deletes the view is not
// followed by a test on an index that moved). One statement per line: Gmsh runs a For loop by
// rewinding its input to the line after For.
std::string for_our_views(const std::vector<std::string>& names, const std::string& body,
                          bool backwards) {
  std::string any;
  for (const auto& n : names)
    any += std::string(any.empty() ? "" : " || ") + "(StrCmp(Sprintf(View[cvt_v].Name), \"" + n +
           "\") == 0)";
  std::string s = "If (PostProcessing.NbViews > 0)\n";
  s += backwards ? "For cvt_v In {PostProcessing.NbViews - 1 : 0 : -1}\n"
                 : "For cvt_v In {0 : PostProcessing.NbViews - 1}\n";
  return s + "If (" + any + ")\n" + body + "EndIf\nEndFor\nEndIf\n";
}

// Renames the views of the last run "<name> (stale)" (the options changed since).
std::string stale_script() {
  const std::vector<std::string> names = our_view_names(false);
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string one = "View[cvt_v].Name = \"" + names[i] + kStaleSuffix + "\";\n";
    s += for_our_views({names[i]}, one, false);
  }
  return s;
}

// The histograms as a list-based view drawn as a 2D graph (the .geo twin of
// gui_add_histogram_view): scalar points along x, two per bin, one time step per series.
std::string histogram_script(const std::vector<QualityHistogram>& series) {
  const std::size_t bins = series.front().fraction.size();
  std::string s = "View \"" + kHistogramViewName + "\" {\n";
  double top = 0;
  char buf[64];
  for (std::size_t b = 0; b < bins; ++b)
    for (int side = 0; side < 2; ++side) {
      std::snprintf(buf, sizeof buf, "SP(%.6g, 0, 0){", static_cast<double>(b + side) / bins);
      s += buf;
      for (std::size_t k = 0; k < series.size(); ++k) {
        const double pct = 100 * series[k].fraction[b];
        top = std::max(top, pct);
        std::snprintf(buf, sizeof buf, "%s%.6g", k ? ", " : "", pct);
        s += buf;
      }
      s += "};\n";
    }
  s += "};\ncvt_h = PostProcessing.NbViews - 1;\n";
  std::snprintf(buf, sizeof buf, "View[cvt_h].CustomMax = %.6g;\n", top > 0 ? top : 1);
  s += "View[cvt_h].Type = 2;\nView[cvt_h].Axes = 2;\nView[cvt_h].AxesLabelX = \"Q\";\n"
       "View[cvt_h].AxesFormatX = \"%.1f\";\nView[cvt_h].AxesFormatY = \"%.0f\";\n"
       "View[cvt_h].ShowTime = 0;\nView[cvt_h].RangeType = 2;\n"
       "View[cvt_h].CustomMin = 0;\n" +
       std::string(buf) +
       "View[cvt_h].LineWidth = 2;\n"
       "View[cvt_h].AutoPosition = 0;\nView[cvt_h].PositionX = 60;\nView[cvt_h].PositionY = 40;\n"
       "View[cvt_h].Width = General.GraphicsWidth * 0.26;\n"
       "View[cvt_h].Height = General.GraphicsHeight * 0.22;\n";
  return s;
}

// .geo-language text that shows the result in the GUI in place of the model: removes the views
// of an earlier run (by name, stale or not), replaces the model by the result ("Delete Model;
// Merge" -- the project file stays the model's, so the next Run re-meshes it), and shows the new
// Q view like cvtmesh-gui does: alone, over the range of its values, in 3D cut by the plane
// through the centre that faces the camera (whole elements), with the result's histogram as a
// graph.
std::string load_script(const MeshData& data, const std::string& path,
                        const std::vector<ElementField>& fields,
                        const std::vector<QualityHistogram>& histograms) {
  std::string s = for_our_views(our_view_names(true), "Delete View[cvt_v];\n", true);
  s += "Delete Model;\nMerge \"" + path + "\";\n";
  if (fields.empty()) return s;
  s += "cvt_q = PostProcessing.NbViews - " + std::to_string(fields.size()) + ";\n";
  s += quality_view_geo(data, fields, "cvt_q");
  if (!histograms.empty()) s += histogram_script(histograms);
  return s;
}

QualityHistogram histogram(const MeshData& d, const std::string& label) {
  return quality_histogram(
      d.dim == 3 ? element_qualities(d.tet, Measure::kQ) : element_qualities(d.tri, Measure::kQ),
      20, label);
}

// The options of the last run, kept in the tree (hidden) to tell when they change.
const std::string kRunOptions = plugin::kGroup + "/9Results/run options";
// 1 when the last compute found a surface mesh in space (the panel is then the 3D one).
const std::string kSurfaceMesh = plugin::kGroup + "/9Results/surface mesh";

int compute(plugin::RemoteOnelab& tree) {
  const std::string in = tree.string("Gmsh/MshFileName").value_or("");
  if (in.empty()) {
    tree.error("cvtmesh: Gmsh did not give a mesh file (Gmsh/MshFileName); mesh the model first");
    return 1;
  }
  tree.progress("cvtmesh: reading " + in);
  MeshData data = read_mesh(in);
  // A surface mesh in space is optimized as a 3D mesh though Gmsh says the model is 2D: the 3D
  // panel, with the 3D default method (the one picked in the other dimension's list does not
  // apply), and remembered (hidden) for the next calls of the client.
  const bool surface_mesh = data.dim == 3 && is_surface_mesh(data.tet);
  OnelabParam surface;
  surface.name = kSurfaceMesh;
  surface.number = surface_mesh ? 1 : 0;
  surface.visible = false;
  surface.never_changed = true;
  tree.set(surface);
  if (data.dim != plugin::panel_dim(tree)) {
    plugin::PanelPreset preset;
    if (!methods_for_dim(data.dim).empty()) preset.method = methods_for_dim(data.dim).front();
    plugin::define_panel(tree, data.dim, preset);
  }
  GmshOptimizeOptions o = plugin::read_panel(tree);
  const std::string signature = plugin::panel_signature(o);
  const int max_it = o.optimize.max_iterations;
  o.optimize.progress = [&](const OptimizeProgress& p) {
    tree.progress(plugin::progress_text(p, max_it));
  };
  tree.info("cvtmesh: optimizing " + in + " with " + o.optimize.method + "...");
  GmshOptimizeResult r;
  r.result = optimize(data, o.optimize);
  r.method = o.optimize.method;
  r.dim = data.dim;
  r.surface_mesh = surface_mesh;

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
  std::vector<QualityHistogram> histograms;
  if (o.quality_views) histograms = {histogram(data, "after")};
  tree.parse_string(load_script(data, out, w.fields, histograms));
  OnelabParam run_options;
  run_options.name = kRunOptions;
  run_options.is_string = true;
  run_options.text = o.quality_views ? signature : "";
  run_options.visible = false;
  run_options.never_changed = true;
  tree.set(run_options);
  return 0;
}

// On check (a parameter changed): the views of the last run are marked stale once the options
// differ from those it ran with.
void check(plugin::RemoteOnelab& tree) {
  const std::string ran = tree.string(kRunOptions).value_or("");
  if (ran.empty()) return;
  std::string now;
  try {
    now = plugin::panel_signature(plugin::read_panel(tree));
  } catch (const std::exception& e) {
    now = std::string("invalid: ") + e.what();
  }
  if (now == ran) return;
  tree.parse_string(stale_script());
  tree.info("cvtmesh: the options changed since the run: its views are marked (stale)");
  OnelabParam run_options;
  run_options.name = kRunOptions;
  run_options.is_string = true;
  run_options.visible = false;
  run_options.never_changed = true;
  tree.set(run_options);
}

}  // namespace

int main(int argc, char** argv) {
  cvtmesh::prefer_passive_openmp_threads(argv);
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
    if (dim == 2 && tree->number(kSurfaceMesh).value_or(0) == 1) dim = 3;
    plugin::define_panel(*tree, dim == 2 ? 2 : 3);
    if (action == "compute") return compute(*tree);
    if (action == "check") check(*tree);
    return 0;
  } catch (const std::exception& e) {
    tree->error(std::string("cvtmesh: ") + e.what());
    return 1;
  }
}
