#include "plugin/panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/pipeline/optimize.h"
#include "core/util/error.h"

namespace cvtmesh::plugin {
namespace {

const std::string kMethod = kGroup + "/0Method";
const std::string kIterations = kGroup + "/1Max iterations";
const std::string kTolerance = kGroup + "/2Tolerance";
const std::string kStep = kGroup + "/2Lloyd step";  // sorts before Tolerance
// The Lloyd step: the dimension's default (L-BFGS in 3D, Anderson in 2D), L-BFGS on the CVT
// energy, over-relaxed Lloyd with Anderson mixing, or the paper's plain step.
const std::vector<std::string> kSteps = {"default", "L-BFGS", "Anderson", "plain (paper)"};
const std::string kSizing = kGroup + "/3Sizing";
const std::string kViews = kGroup + "/4Quality views";
const std::string kDim = kGroup + "/dim";
const std::string kResults = kGroup + "/9Results/";
const std::vector<std::string> kSizings = {"mesh", "uniform"};

OnelabParam input(const std::string& name, double value, const std::string& help) {
  OnelabParam p;
  p.name = name;
  p.number = value;
  p.help = help;
  p.attributes = {{"Highlight", "AliceBlue"}};
  return p;
}

OnelabParam result(const std::string& label, double value) {
  OnelabParam p;
  p.name = kResults + label;
  p.number = value;
  p.read_only = true;
  p.never_changed = true;
  p.attributes = {{"Highlight", "Ivory"}};
  return p;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

}  // namespace

std::vector<std::string> all_methods() {
  std::vector<std::string> all = methods_for_dim(3);
  for (const auto& m : methods_for_dim(2))
    if (std::find(all.begin(), all.end(), m) == all.end()) all.push_back(m);
  return all;
}

void define_panel(OnelabTree& tree, int dim, const PanelPreset& preset) {
  dim = dim == 2 ? 2 : 3;
  const std::vector<std::string> all = all_methods();
  const std::vector<std::string> here = methods_for_dim(dim);

  OnelabParam method = input(
      kMethod, 0,
      "Du & Wang's methods for " + std::to_string(dim) + "D meshes (cvdt: Lloyd CVT + Delaunay)");
  for (const auto& m : here) {
    const auto code = std::find(all.begin(), all.end(), m) - all.begin();
    method.choices.push_back(static_cast<double>(code));
    method.labels.push_back(m);
  }
  method.number = method.choices.empty() ? 0 : method.choices.front();
  if (auto cur = tree.number(kMethod))
    if (std::find(method.choices.begin(), method.choices.end(), *cur) != method.choices.end())
      method.number = *cur;
  if (!preset.method.empty()) {
    const auto m = std::find(here.begin(), here.end(), preset.method);
    if (m == here.end())
      throw InputError("method '" + preset.method + "' does not apply to " + std::to_string(dim) +
                       "D meshes (available: " + join(here) + ")");
    method.number = method.choices[m - here.begin()];
  }
  method.attributes.clear();  // Highlight colours a drop-down's text, not its background
  tree.set(method);

  OnelabParam it =
      input(kIterations, OptimizeOptions{}.max_iterations, "Lloyd / outer iterations at most");
  it.min = 1;
  it.max = 1000;
  it.step = 1;
  if (auto cur = tree.number(kIterations)) it.number = *cur;
  if (preset.max_iterations >= 0) it.number = preset.max_iterations;
  tree.set(it);

  OnelabParam tol = input(kTolerance, OptimizeOptions{}.tolerance,
                          "Lloyd stops when the mean squared relative move D is below this");
  if (auto cur = tree.number(kTolerance)) tol.number = *cur;
  if (preset.tolerance >= 0) tol.number = preset.tolerance;
  tree.set(tol);

  OnelabParam step = input(kStep, 0,
                           "CVT (Lloyd) step: default = L-BFGS in 3D, Anderson in 2D; L-BFGS = "
                           "quasi-Newton on the CVT energy (fewest iterations); Anderson = "
                           "over-relaxed Lloyd with Anderson mixing; plain = the paper's step");
  for (std::size_t i = 0; i < kSteps.size(); ++i) {
    step.choices.push_back(static_cast<double>(i));
    step.labels.push_back(kSteps[i]);
  }
  if (auto cur = tree.number(kStep)) step.number = *cur;
  step.attributes.clear();
  tree.set(step);

  OnelabParam sizing = input(kSizing, 0,
                             "Density: mesh = keep the input's local edge length (grading), "
                             "uniform = constant size");
  for (std::size_t i = 0; i < kSizings.size(); ++i) {
    sizing.choices.push_back(static_cast<double>(i));
    sizing.labels.push_back(kSizings[i]);
  }
  if (auto cur = tree.number(kSizing)) sizing.number = *cur;
  sizing.attributes.clear();
  if (!preset.sizing.empty()) {
    const auto k = std::find(kSizings.begin(), kSizings.end(), preset.sizing);
    if (k == kSizings.end())
      throw InputError("sizing '" + preset.sizing +
                       "' is not offered (available: " + join(kSizings) + ")");
    sizing.number = static_cast<double>(k - kSizings.begin());
  }
  tree.set(sizing);

  OnelabParam views = input(kViews, 1, "Add per-element quality views (Q, radius ratio, angle)");
  views.choices = {0, 1};
  if (auto cur = tree.number(kViews)) views.number = *cur;
  if (preset.quality_views >= 0) views.number = preset.quality_views ? 1 : 0;
  tree.set(views);

  OnelabParam d;
  d.name = kDim;
  d.number = dim;
  d.visible = false;
  d.never_changed = true;
  tree.set(d);
}

void define_quality_button(OnelabTree& tree, const std::string& action) {
  OnelabParam b;
  b.name = kGroup + "/5Show quality";
  b.is_string = true;
  b.text = action;
  b.never_changed = true;
  b.help = "Colour the current mesh by quality (Q) without changing it";
  b.attributes = {{"Macro", "Action"}, {"Aspect", "Button"}};
  tree.set(b);
}

int panel_dim(OnelabTree& tree) {
  const auto d = tree.number(kDim);
  return d ? static_cast<int>(*d) : 0;
}

GmshOptimizeOptions read_panel(OnelabTree& tree) {
  GmshOptimizeOptions o;
  const std::vector<std::string> all = all_methods();
  const int dim = panel_dim(tree);
  if (dim && methods_for_dim(dim).empty())
    throw InputError("no optimization method is available for " + std::to_string(dim) +
                     "D meshes in this build");
  const double code = tree.number(kMethod).value_or(0);
  if (code < 0 || code >= static_cast<double>(all.size()) || code != std::floor(code))
    throw InputError("unknown method (value " + std::to_string(code) + ") in the panel");
  o.optimize.method = all[static_cast<std::size_t>(code)];
  o.optimize.max_iterations =
      std::max(1, static_cast<int>(std::lround(tree.number(kIterations).value_or(100))));
  o.optimize.tolerance = tree.number(kTolerance).value_or(o.optimize.tolerance);
  if (!(o.optimize.tolerance >= 0)) throw InputError("the tolerance must be a number >= 0");
  const auto s = static_cast<std::size_t>(std::lround(tree.number(kSizing).value_or(0)));
  o.optimize.sizing = kSizings[std::min(s, kSizings.size() - 1)];
  o.quality_views = tree.number(kViews).value_or(1) != 0;
  switch (std::lround(tree.number(kStep).value_or(0))) {
    case 1:
      o.optimize.lbfgs_memory = 5;
      break;
    case 2:
      o.optimize.lbfgs_memory = 0;
      break;
    case 3:
      o.optimize.lbfgs_memory = 0;
      o.optimize.anderson_depth = 0;
      o.optimize.relaxation = 1.0;
      break;
    default:
      break;
  }
  o.dim = dim ? dim : -1;
  return o;
}

void show_results(OnelabTree& tree, const GmshOptimizeResult& r) {
  const QualityStats& b = r.result.before;
  const QualityStats& a = r.result.after;
  tree.set(result("0Iterations", r.result.iterations));
  tree.set(result("1Time (s)", std::round(r.result.seconds * 100) / 100));
  tree.set(result("2Q avg", a.q_avg));
  tree.set(result("3Q avg (init)", b.q_avg));
  tree.set(result("4Q min", a.q_min));
  tree.set(result("5Q min (init)", b.q_min));
  tree.set(result("6Bad % Q<0.3", a.bad_pct));
  tree.set(result("7Bad % (init)", b.bad_pct));
}

std::string summary(const GmshOptimizeResult& r) {
  const QualityStats& b = r.result.before;
  const QualityStats& a = r.result.after;
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "cvtmesh: %s on %ld %s: %d iterations%s, %.2f s; Q avg %.4f -> %.4f, Q min %.4f "
                "-> %.4f, bad (Q<0.3) %.2f%% -> %.2f%%",
                r.method.c_str(), a.nb_elements, r.dim == 3 ? "tetrahedra" : "triangles",
                r.result.iterations, r.result.converged ? " (converged)" : "", r.result.seconds,
                b.q_avg, a.q_avg, b.q_min, a.q_min, b.bad_pct, a.bad_pct);
  return buf;
}

std::string progress_text(const OptimizeProgress& p, int max_iterations) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "cvtmesh: %s iteration %d/%d, Q avg %.4f, Q min %.4f",
                p.phase.c_str(), p.iteration, max_iterations, p.q_avg, p.q_min);
  return buf;
}

}  // namespace cvtmesh::plugin
