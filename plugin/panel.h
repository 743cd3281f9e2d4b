// The "Mesh optimization (CVT)" group of the ONELAB tree, shared by the GUI panel (cvtmesh-gui)
// and the ONELAB client of a stock Gmsh (cvtmesh-onelab): its inputs (method, max iterations,
// tolerance, sizing, quality views), reading them as options, and its read-only results.
#pragma once
#include <string>
#include <vector>

#include "plugin/gmsh_gui.h"
#include "plugin/gmsh_inprocess.h"

namespace cvtmesh::plugin {

inline const std::string kGroup = "Mesh optimization (CVT)";

// Every method the core offers (3D then 2D, no repeats); a method's ONELAB value is its index here,
// so that a choice survives switching between a 2D and a 3D model when the method exists in both.
std::vector<std::string> all_methods();

// Values for the inputs (the command line of cvtmesh-gui): an empty method/sizing or a negative
// value keeps what the tree holds.
struct PanelPreset {
  std::string method;
  int max_iterations = -1;
  double tolerance = -1;
  std::string sizing;
  int quality_views = -1;  // 0/1
};

// Creates the inputs for a model of dimension dim (2 or 3; the method list depends on it). Values
// already in the tree are kept unless the preset gives one (a method that does not apply to dim
// falls back to the first one). Throws InputError for a preset method or sizing not offered.
void define_panel(OnelabTree& tree, int dim, const PanelPreset& preset = {});
// A "Show quality" button in the group (GUI only): pressing it sets ONELAB/Action to `action`.
void define_quality_button(OnelabTree& tree, const std::string& action);

// The dimension define_panel was last called with (0 if never).
int panel_dim(OnelabTree& tree);

// The options the inputs say. Throws InputError for a method the tree does not offer.
GmshOptimizeOptions read_panel(OnelabTree& tree);

// The options as one line of text (every schema option's value, the quality views): two runs
// with the same signature ran with the same options. What marks a run's views stale.
std::string panel_signature(const GmshOptimizeOptions& o);

// Writes the read-only results (iterations, time, Q avg/min and bad % before and after).
void show_results(OnelabTree& tree, const GmshOptimizeResult& r);

// One line for the message console, and a progress line for the status bar.
std::string summary(const GmshOptimizeResult& r);
std::string progress_text(const OptimizeProgress& p, int max_iterations);

}  // namespace cvtmesh::plugin
