#include "plugin/panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/pipeline/option_schema.h"
#include "core/pipeline/optimize.h"
#include "core/util/error.h"

namespace cvtmesh::plugin {
namespace {

// The inputs come from the option schema (core/pipeline/option_schema.h: the options with a panel
// label) and its Lloyd-step presets; only the quality-views switch is the panel's own.
const OptionSpec& spec(const char* name) {
  return *find_option(name);
}
std::string param_name(const OptionSpec& s) {
  return kGroup + "/" + s.panel;
}
const std::string kMethod = param_name(spec("method"));
const std::string kStep = kGroup + "/2Lloyd step";  // sorts before Tolerance
const std::string kViews = kGroup + "/4Quality views";
const std::string kDim = kGroup + "/dim";
const std::string kResults = kGroup + "/9Results/";
// The sizings a panel user can pick (the schema's, but "function" needs a C++ size function).
std::vector<std::string> panel_sizings() {
  std::vector<std::string> v;
  for (const auto& c : spec("sizing").choices)
    if (c != "function") v.push_back(c);
  return v;
}

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

  OnelabParam method =
      input(kMethod, 0,
            "Du & Wang's methods for " + std::to_string(dim) + "D meshes:\n" + methods_help(dim));
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

  // The numeric options with a panel label, their range from the schema.
  for (const OptionSpec& s : option_schema()) {
    if (s.panel.empty() || s.name == "method" || s.name == "sizing") continue;
    if (!(s.dims & (dim == 2 ? kDim2 : kDim3))) continue;
    // The dimension's own defaults (the -1 of max_iterations and tolerance resolved).
    OnelabParam p =
        input(param_name(s), value_number(s, resolve(OptimizeOptions{}, dim)), describe(s));
    if (std::isfinite(s.min)) p.min = s.min;
    if (std::isfinite(s.max)) p.max = s.max;
    if (!std::holds_alternative<double OptimizeOptions::*>(s.field)) p.step = 1;
    if (std::holds_alternative<bool OptimizeOptions::*>(s.field)) p.choices = {0, 1};  // a box
    if (auto cur = tree.number(p.name)) p.number = *cur;
    if (s.name == "max_iterations" && preset.max_iterations >= 0) p.number = preset.max_iterations;
    if (s.name == "tolerance" && preset.tolerance >= 0) p.number = preset.tolerance;
    tree.set(p);
  }

  std::string step_help = "CVT (Lloyd) step:";
  for (const OptionPreset& p : lloyd_step_presets())
    step_help += " " + p.name + " = " + p.help + ";";
  OnelabParam step = input(kStep, 0, step_help);
  for (std::size_t i = 0; i < lloyd_step_presets().size(); ++i) {
    step.choices.push_back(static_cast<double>(i));
    step.labels.push_back(lloyd_step_presets()[i].name);
  }
  if (auto cur = tree.number(kStep)) step.number = *cur;
  step.attributes.clear();
  tree.set(step);

  const std::vector<std::string> sizings = panel_sizings();
  OnelabParam sizing = input(param_name(spec("sizing")), 0, describe(spec("sizing")));
  for (std::size_t i = 0; i < sizings.size(); ++i) {
    sizing.choices.push_back(static_cast<double>(i));
    sizing.labels.push_back(sizings[i]);
  }
  if (auto cur = tree.number(sizing.name)) sizing.number = *cur;
  sizing.attributes.clear();
  if (!preset.sizing.empty()) {
    const auto k = std::find(sizings.begin(), sizings.end(), preset.sizing);
    if (k == sizings.end())
      throw InputError("sizing '" + preset.sizing +
                       "' is not offered (available: " + join(sizings) + ")");
    sizing.number = static_cast<double>(k - sizings.begin());
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
  // The Lloyd step preset first, then the numeric inputs, each set and checked by the schema.
  const auto step = static_cast<std::size_t>(std::lround(tree.number(kStep).value_or(0)));
  apply_preset(lloyd_step_presets()[std::min(step, lloyd_step_presets().size() - 1)].name,
               o.optimize);
  for (const OptionSpec& s : option_schema()) {
    if (s.panel.empty() || s.name == "method" || s.name == "sizing") continue;
    // An input of the other dimension's panel (left in the tree) does not apply here.
    if (dim && !(s.dims & (dim == 2 ? kDim2 : kDim3))) continue;
    if (auto v = tree.number(param_name(s))) set_number(s, o.optimize, *v);
  }
  const std::vector<std::string> sizings = panel_sizings();
  const auto k =
      static_cast<std::size_t>(std::lround(tree.number(param_name(spec("sizing"))).value_or(0)));
  o.optimize.sizing = sizings[std::min(k, sizings.size() - 1)];
  o.quality_views = tree.number(kViews).value_or(1) != 0;
  o.dim = dim ? dim : -1;
  validate(o.optimize, dim);  // the same refusal as the CLI and Python, before any work starts
  return o;
}

std::string panel_signature(const GmshOptimizeOptions& o) {
  std::string s;
  for (const OptionSpec& spec : option_schema())
    s += spec.name + "=" + value_text(spec, o.optimize) + ";";
  return s + "quality_views=" + std::to_string(o.quality_views) + ";dim=" + std::to_string(o.dim);
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
                r.method.c_str(), a.nb_elements,
                r.dim == 3 && !r.surface_mesh ? "tetrahedra" : "triangles", r.result.iterations,
                r.result.converged ? " (converged)" : "", r.result.seconds, b.q_avg, a.q_avg,
                b.q_min, a.q_min, b.bad_pct, a.bad_pct);
  return buf;
}

std::string progress_text(const OptimizeProgress& p, int max_iterations) {
  if (p.start) return "cvtmesh: " + p.phase + "...";  // a phase begins: no figures yet
  char buf[200];
  std::snprintf(buf, sizeof buf, "cvtmesh: %s iteration %d/%d, Q avg %.4f, Q min %.4f",
                p.phase.c_str(), p.iteration, max_iterations, p.q_avg, p.q_min);
  return buf;
}

}  // namespace cvtmesh::plugin
