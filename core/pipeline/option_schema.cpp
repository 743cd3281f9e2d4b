#include "core/pipeline/option_schema.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "core/pipeline/method_registry.h"
#include "core/pipeline/optimize.h"
#include "core/pipeline/select_regions.h"

namespace cvtmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

OptionSpec number(std::string name, std::string flag, OptionField f, double lo, double hi,
                  std::string help, int dims = kDim23, int fronts = kCli | kPython) {
  OptionSpec s;
  s.name = std::move(name);
  s.flag = std::move(flag);
  s.field = f;
  s.min = lo;
  s.max = hi;
  s.help = std::move(help);
  s.dims = dims;
  s.fronts = fronts;
  return s;
}

// An option whose -1 stands for the dimension's default (filled in by resolve()).
OptionSpec with_dimension_default(OptionSpec s) {
  s.special = -1;
  s.has_special = true;
  return s;
}

OptionSpec boolean(std::string name, std::string flag, bool OptimizeOptions::*f, std::string help,
                   int dims = kDim23, int fronts = kCli | kPython) {
  OptionSpec s = number(std::move(name), std::move(flag), f, 0, 1, std::move(help), dims, fronts);
  return s;
}

std::vector<OptionSpec> make_schema() {
  using O = OptimizeOptions;
  std::vector<OptionSpec> v;
  {
    OptionSpec s;
    s.name = "method";
    s.flag = "--method";
    s.panel = "0Method";
    s.field = &O::method;
    s.fronts = kAllFronts;
    s.help =
        "the optimization method (one of the registry's for the mesh's dimension; '' = "
        "the dimension's default)";
    v.push_back(s);
  }
  {
    OptionSpec s = number("max_iterations", "--max-iterations", &O::max_iterations, 0, 1e6,
                          "maximum Lloyd / outer iterations (the dimension's default: 100 in "
                          "3D, 1000 in 2D)",
                          kDim23, kAllFronts);
    s.panel = "1Max iterations";
    v.push_back(with_dimension_default(s));
  }
  {
    OptionSpec s = number("tolerance", "--tolerance", &O::tolerance, 0, kInf,
                          "Lloyd stops when the mean squared relative move D is below this ("
                          "the dimension's default: 1e-5 in 3D, 1e-8 in 2D)",
                          kDim23, kAllFronts);
    s.panel = "2Tolerance";
    v.push_back(with_dimension_default(s));
  }
  {
    OptionSpec s;
    s.name = "sizing";
    s.flag = "--sizing";
    s.panel = "3Sizing";
    s.field = &O::sizing;
    s.fronts = kAllFronts;
    s.choices = {"mesh", "uniform", "function"};
    s.or_path = true;
    s.help =
        "sizing field H of the density 1/H^(d+2): mesh (the input's local edge length, "
        "keeps its grading; for a .geo input the model's own mesh sizes), uniform, function "
        "(C++: size_function), or a FILE: a reference mesh's local edge length (a .geo is "
        "meshed by Gmsh first: the model's own sizes)";
    v.push_back(s);
  }
  {
    OptionSpec s;
    s.name = "regions";
    s.flag = "--regions";
    s.field = &O::regions;
    s.dims = kDim3;
    s.fronts = kCli | kPython;
    s.help =
        "optimize only these volumes (entity tags, e.g. 1,3; '' = every volume): the others are "
        "kept exactly, the selection's boundary and interfaces fixed";
    v.push_back(s);
  }
  {
    OptionSpec s;
    s.name = "physical";
    s.flag = "--physical";
    s.field = &O::physical;
    s.dims = kDim3;
    s.fronts = kCli | kPython;
    s.help =
        "optimize only the volumes of the physical group of this name (with --regions: both); "
        "the others are kept exactly, the selection's boundary and interfaces fixed";
    v.push_back(s);
  }
  v.push_back(number("relaxation", "--relaxation", &O::relaxation, 0.05, 1.95,
                     "Lloyd over-relaxation omega (1 = the paper's plain step; also scales "
                     "L-BFGS's initial inverse Hessian)"));
  v.push_back(number("anderson", "--anderson", &O::anderson_depth, 0, 20,
                     "Anderson acceleration depth of Lloyd's step (0 = plain Lloyd)"));
  {
    OptionSpec s = number("lbfgs", "--lbfgs", &O::lbfgs_memory, 0, 50,
                          "minimise the CVT energy by L-BFGS with this memory instead of Lloyd's "
                          "step (0 = Lloyd's step with relaxation/anderson; -1 = the dimension's "
                          "default: 5 in 3D, 0 in 2D). The paper's plain Lloyd: lbfgs 0, "
                          "anderson 0, relaxation 1");
    v.push_back(with_dimension_default(s));
  }
  v.push_back(number("hops", "--hops", &O::hops, 0, 100000,
                     "basin-hopping trials after Lloyd converges (0 = off): kick every free "
                     "vertex randomly, re-run Lloyd, keep the mesh of lowest CVT energy",
                     kDim2));
  v.push_back(number("hop_amount", "--hop-amount", &O::hop_amount, 0.01, 1.0,
                     "basin-hopping kick radius, in units of the local size h", kDim2));
  v.push_back(number("seed", "--seed", &O::seed, 0, 4294967295.0,
                     "random seed (methods that use randomness: hops)"));
  v.push_back(number("swap_below", "--swap-below", &O::swap_below, 0, kInf,
                     "SWAP tries only the tets whose Q is below this (inf: all tets)", kDim3));
  v.push_back(number("polish_flip_below", "--polish-flip-below", &O::polish_flip_below, 0, kInf,
                     "the polish's dihedral flips try only tets with a dihedral angle below this "
                     "many degrees (inf: all tets)",
                     kDim3));
  v.push_back(number("polish_q_floor", "--polish-q-floor", &O::polish_q_floor, 0, 1,
                     "the polish's dihedral flips never lower a tet's Q below min(its old "
                     "minimum, this floor)",
                     kDim3));
  v.push_back(boolean("polish_maxmin", "--no-polish-maxmin", &O::polish_maxmin,
                      "the polish's max-min smoothing of the poor tets' vertices (the flag "
                      "turns it off)",
                      kDim3));
  v.push_back(boolean("polish_repair", "--no-polish-repair", &O::polish_repair,
                      "the polish's final repair of its slivers: vertex insertion or flips with "
                      "local smoothing, kept where the local minimum rises (the flag turns it "
                      "off)",
                      kDim3));
  // The time step (issue 16; core/quality/time_step_guard.h).
  {
    OptionSpec s;
    s.name = "objective";
    s.flag = "--objective";
    s.field = &O::objective;
    s.dims = kDim3;
    s.fronts = kCli | kPython;
    s.choices = {"quality", "dt"};
    s.help =
        "the polish's main criterion: quality (Q and dihedral angles) or dt (the element "
        "explicit time step: flips maximise it, moves never lower a star's)";
    v.push_back(s);
  }
  v.push_back(boolean("polish_dt_guard", "--no-polish-dt-guard", &O::polish_dt_guard,
                      "the polish's time-step guard: its moves, flips and repairs never lower a "
                      "star's smallest element time step below min(its old value, polish_dt_floor "
                      "x the mesh's smallest) (the flag turns it off)",
                      kDim3));
  v.push_back(number("polish_dt_floor", "--polish-dt-floor", &O::polish_dt_floor, 1, kInf,
                     "the time-step guard protects the element time steps below this factor "
                     "times the mesh's smallest (inf: every star's smallest step)",
                     kDim3));
  // The free boundary (issue 13; core/boundary/), in the panel's group "Free boundary".
  auto panel = [&v](OptionSpec s, const char* label) {
    s.fronts = kAllFronts;
    s.panel = std::string("6Free boundary/") + label;
    v.push_back(std::move(s));
  };
  panel(boolean("fix_boundary", "--fix-boundary", &O::fix_boundary,
                "keep every boundary vertex fixed (the default method otherwise moves "
                "surface and curve vertices on the input's geometry; the other methods "
                "always keep it fixed)",
                kDim3),
        "0Fix boundary");
  panel(number("hausdorff", "--hausdorff", &O::hausdorff, 0, kInf,
               "free boundary: bound on the two-sided Hausdorff distance between the new "
               "and the input boundary, in model units (0 = 2e-3 of the bounding-box "
               "diagonal; on a CAD model, on top of the input mesh's own distance to the CAD)",
               kDim3),
        "1Hausdorff bound");
  panel(number("feature_angle", "--feature-angle", &O::feature_angle, 0, 180,
               "free boundary: edges where the surface turns by more than this many "
               "degrees are sharp features, kept as curves",
               kDim3),
        "2Feature angle");
  panel(boolean("free_smooth_curves", "--free-smooth-curves", &O::free_smooth_curves,
                "free boundary: Gmsh curves and points across which the surface is smooth "
                "are not kept; their vertices move on the surface",
                kDim3),
        "3Free smooth curves");
  panel(number("volume_tolerance", "--volume-tolerance", &O::volume_tolerance, 0, 1,
               "free boundary: bound on each region's relative volume change", kDim3),
        "4Volume tolerance");
  panel(
      number("boundary_lloyd_rounds", "--boundary-lloyd-rounds", &O::boundary_lloyd_rounds, 0, 1000,
             "free boundary: constrained-CVT rounds of the boundary after Lloyd (0 = "
             "none)",
             kDim3),
      "5CVT rounds");
  v.push_back(number("mean_passes", "--mean-passes", &O::mean_passes, 0, 20,
                     "free boundary: passes of the average-quality smoothing (each vertex moved "
                     "to raise its star's sum of Q, the minimum kept) and the flips on the "
                     "average at the end, at most (a pass follows only one that raised the "
                     "average Q by 0.008 or more; 0 = none)",
                     kDim3));
  v.push_back(number("coarsen_surface", "--coarsen-surface", &O::coarsen_surface, 0, 1,
                     "free boundary: surface edges shorter than this fraction of the interior "
                     "spacing near them are collapsed (surface vertices removed, under the "
                     "Hausdorff and volume bounds) after the first Lloyd (0 = none)",
                     kDim3));
  {
    // 0 (none) or TetGen's radius-edge bound, which must exceed 1.
    OptionSpec s = number("refine_interior", "--refine-interior", &O::refine_interior, 1.05, 10,
                          "cvdt methods: before Lloyd, add interior vertices where a tet's "
                          "circumradius exceeds this times its shortest edge (TetGen's quality "
                          "bound, the boundary kept; 1.2 for a coarse model; 0 = none)",
                          kDim3);
    s.special = 0;
    s.has_special = true;
    v.push_back(s);
  }
  {
    OptionSpec s = boolean("auto_refine", "--no-auto-refine", &O::auto_refine,
                           "default method, no --refine-interior: on a coarse model whose result "
                           "misses average Q 0.85 or Q_min 0.40, the run with the interior "
                           "refined (bound 1.5, then 1.2) is kept where it is no worse on every "
                           "quality row (up to 1 % of Q_min, 0.001 of the average, 0.1 degrees) "
                           "or better on both Q rows for a little of an angle row, never worse "
                           "than the input, and better (the higher average of two; more "
                           "elements; after a kept 1.2 run, a 1.1 run judged the same way "
                           "against it; the flag turns it off)",
                           kDim3);
    s.fronts = kAllFronts;
    s.panel = "4Refine a coarse interior";
    v.push_back(s);
  }
  v.push_back(number("auto_refine_max_tets", "--auto-refine-max-tets", &O::auto_refine_max_tets, 0,
                     2e9,
                     "auto_refine tries the refinement only on inputs of at most this "
                     "many tets",
                     kDim3));
  // Issue 14 (robust branch): Python only for now; the CLI has --allow-worse (cmd_optimize.cpp).
  v.push_back(boolean("never_worse", "", &O::never_worse,
                      "never worse than the input: a result with a lower Q_min or min angle or a "
                      "higher max angle falls back to the polish alone, or to the input",
                      kDim23, kPython));
  v.push_back(boolean("verify", "", &O::verify,
                      "check the invariants of the result against the input (InvariantError)",
                      kDim23, 0));
  return v;
}

std::string fmt(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  if (std::isnan(x)) return "nan";
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", x);
  return b;
}

bool is_string(const OptionSpec& s) {
  return std::holds_alternative<std::string OptimizeOptions::*>(s.field);
}
bool is_bool(const OptionSpec& s) {
  return std::holds_alternative<bool OptimizeOptions::*>(s.field);
}
bool is_integral(const OptionSpec& s) {
  return std::holds_alternative<int OptimizeOptions::*>(s.field) ||
         std::holds_alternative<unsigned OptimizeOptions::*>(s.field);
}

std::string range_text(const OptionSpec& s) {
  if (is_bool(s)) return "true or false";
  if (is_string(s)) {
    if (s.choices.empty()) return "any text";
    std::string c;
    for (const auto& x : s.choices) c += (c.empty() ? "" : ", ") + x;
    return "one of " + c + (s.or_path ? " or a file" : "");
  }
  std::string r =
      (is_integral(s) ? "an integer in [" : "a number in [") + fmt(s.min) + ", " + fmt(s.max) + "]";
  if (s.has_special) r += " or " + fmt(s.special) + " (default)";
  return r;
}

[[noreturn]] void refuse(const OptionSpec& s, const std::string& value, const std::string& why) {
  std::string where = s.name;
  if (!s.flag.empty()) where += " (" + s.flag + ")";
  throw OptionError(s.name, value, "invalid value " + value + " for option " + where + ": " + why);
}

}  // namespace

const std::vector<OptionSpec>& option_schema() {
  static const std::vector<OptionSpec> schema = make_schema();
  return schema;
}

const OptionSpec* find_option(std::string_view name) {
  for (const OptionSpec& s : option_schema())
    if (s.name == name || (!s.flag.empty() && s.flag == name)) return &s;
  return nullptr;
}

double value_number(const OptionSpec& s, const OptimizeOptions& o) {
  return std::visit(
      [&](auto f) -> double {
        using T = std::decay_t<decltype(o.*f)>;
        if constexpr (std::is_same_v<T, std::string>)
          throw std::logic_error("option " + s.name + " is not a number");
        else
          return static_cast<double>(o.*f);
      },
      s.field);
}

std::string value_text(const OptionSpec& s, const OptimizeOptions& o) {
  if (is_string(s)) return o.*std::get<std::string OptimizeOptions::*>(s.field);
  if (is_bool(s)) return o.*std::get<bool OptimizeOptions::*>(s.field) ? "true" : "false";
  return fmt(value_number(s, o));
}

bool is_default(const OptionSpec& s, const OptimizeOptions& o) {
  return value_text(s, o) == value_text(s, OptimizeOptions{});
}

void set_number(const OptionSpec& s, OptimizeOptions& o, double v) {
  std::visit(
      [&](auto f) {
        using T = std::decay_t<decltype(o.*f)>;
        if constexpr (std::is_same_v<T, std::string>) {
          refuse(s, fmt(v), "expected " + range_text(s));
        } else if constexpr (std::is_same_v<T, bool>) {
          if (v != 0 && v != 1) refuse(s, fmt(v), "expected true or false (1 or 0)");
          o.*f = v != 0;
        } else if constexpr (std::is_integral_v<T>) {
          // Whole numbers only, and within the type (the range check comes in validate).
          if (!(v == std::floor(v)) || v < static_cast<double>(std::numeric_limits<T>::min()) ||
              v > static_cast<double>(std::numeric_limits<T>::max()))
            refuse(s, fmt(v), "expected " + range_text(s));
          o.*f = static_cast<T>(v);
        } else {
          o.*f = v;
        }
      },
      s.field);
}

void set_text(const OptionSpec& s, OptimizeOptions& o, const std::string& v) {
  if (is_string(s)) {
    o.*std::get<std::string OptimizeOptions::*>(s.field) = v;
    return;
  }
  if (is_bool(s)) {
    if (v == "true" || v == "1") return set_number(s, o, 1);
    if (v == "false" || v == "0") return set_number(s, o, 0);
    refuse(s, "'" + v + "'", "expected true or false");
  }
  std::size_t used = 0;
  double x = 0;
  try {
    x = std::stod(v, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != v.size()) refuse(s, "'" + v + "'", "expected " + range_text(s));
  set_number(s, o, x);
}

std::string describe(const OptionSpec& s) {
  std::string d = s.help + " (default ";
  const std::string def = value_text(s, OptimizeOptions{});
  if (s.name == "method")
    d += default_method(3) + " in 3D, " + default_method(2) + " in 2D";
  else if (s.has_special && def == fmt(s.special))
    d += def + ": the dimension's default";
  else
    d += def.empty() ? "''" : def;
  if (!is_bool(s) && s.name != "method") d += "; " + range_text(s);
  if (s.dims != kDim23) d += s.dims == kDim2 ? "; 2D only" : "; 3D only";
  return d + ")";
}

void validate(const OptimizeOptions& o, int dim) {
  for (const OptionSpec& s : option_schema()) {
    if (s.name == "method") {
      const std::string& m = o.method;
      if (m.empty() || m == default_method(3)) continue;  // the default of either dimension
      const int dims[] = {2, 3};
      bool known = false;
      for (int d : dims)
        if ((dim == 0 || dim == d) && find_method(m, d)) known = true;
      if (!known) {
        std::string avail;
        for (int d : dims) {
          if (dim != 0 && dim != d) continue;
          for (const auto& n : methods_for_dim(d))
            if ((", " + avail + ", ").find(", " + n + ", ") == std::string::npos)
              avail += (avail.empty() ? "" : ", ") + n;
        }
        refuse(s, "'" + m + "'",
               (dim ? "not a " + std::to_string(dim) + "D method" : std::string("unknown method")) +
                   " (available: " + avail + ")");
      }
      continue;
    }
    if (is_string(s)) {
      const std::string& v = o.*std::get<std::string OptimizeOptions::*>(s.field);
      bool ok = s.choices.empty() || (s.or_path && !v.empty());
      for (const auto& c : s.choices) ok = ok || v == c;
      if (!ok) refuse(s, "'" + v + "'", "expected " + range_text(s));
      if (s.name == "regions") parse_region_tags(v);  // OptionError if not a list of tags
      if (s.name == "sizing" && sizing_is_path(o)) {
        const MeshData* ref = o.sizing_reference.get();
        if (!ref)
          refuse(s, "'" + v + "'",
                 "a reference file is read by the CLI (optimize, compare) only; here use "
                 "mesh, uniform or function (C++: read_sizing_reference into "
                 "sizing_reference)");
        if (dim != 0 && ref->dim != dim)
          refuse(s, "'" + v + "'",
                 "the reference is a " + std::to_string(ref->dim) + "D mesh; this mesh is " +
                     std::to_string(dim) + "D");
      }
      if (s.name == "sizing" && v == "function" && !o.size_function)
        refuse(s, "'function'", "needs a size_function (C++ API)");
    } else if (!is_bool(s)) {
      const double v = value_number(s, o);
      const bool special = s.has_special && v == s.special;
      if (!special && !(v >= s.min && v <= s.max)) refuse(s, fmt(v), "expected " + range_text(s));
    }
    const int here = dim == 2 ? kDim2 : dim == 3 ? kDim3 : kDim23;
    if (!(s.dims & here) && !is_default(s, o))
      refuse(s, value_text(s, o),
             std::string("a ") + (s.dims == kDim2 ? "2D" : "3D") + " option; this mesh is " +
                 std::to_string(dim) + "D");
  }
}

bool sizing_is_path(const OptimizeOptions& o) {
  const OptionSpec* s = find_option("sizing");
  for (const auto& c : s->choices)
    if (o.sizing == c) return false;
  return !o.sizing.empty();
}

OptimizeOptions resolve(const OptimizeOptions& o, int dim) {
  OptimizeOptions r = o;
  if (r.method.empty() || (dim == 2 && r.method == default_method(3)))
    r.method = default_method(dim);
  if (r.lbfgs_memory < 0) r.lbfgs_memory = dim == 3 ? 5 : 0;
  if (r.max_iterations < 0) r.max_iterations = dim == 3 ? 100 : 1000;
  if (r.tolerance < 0) r.tolerance = dim == 3 ? 1e-5 : 1e-8;
  return r;
}

const std::vector<OptionPreset>& lloyd_step_presets() {
  static const std::vector<OptionPreset> p = {
      {"default", "the dimension's default (L-BFGS in 3D, over-relaxed Anderson Lloyd in 2D)", {}},
      {"L-BFGS", "quasi-Newton on the CVT energy (fewest iterations)", {{"lbfgs", 5}}},
      {"Anderson", "over-relaxed Lloyd with Anderson mixing", {{"lbfgs", 0}}},
      {"plain (paper)",
       "the paper's plain Lloyd step",
       {{"lbfgs", 0}, {"anderson", 0}, {"relaxation", 1.0}}},
  };
  return p;
}

void apply_preset(const std::string& name, OptimizeOptions& o) {
  for (const OptionPreset& p : lloyd_step_presets()) {
    if (p.name != name) continue;
    for (const auto& [opt, v] : p.values) set_number(*find_option(opt), o, v);
    return;
  }
  std::string avail;
  for (const OptionPreset& p : lloyd_step_presets()) avail += (avail.empty() ? "" : ", ") + p.name;
  throw OptionError("lloyd_step", name,
                    "unknown Lloyd step '" + name + "' (available: " + avail + ")");
}

}  // namespace cvtmesh
