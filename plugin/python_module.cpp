// The Python module `cvtmesh`: optimizes the current model of the Gmsh loaded in the same Python
// process (Debian's python3-gmsh loads libgmsh.so.4.8; this module links the same library, so both
// see one Gmsh).
//
//   import gmsh, cvtmesh
//   gmsh.initialize(); gmsh.open("cube_sphere.geo"); gmsh.model.mesh.generate(3)
//   table = cvtmesh.optimize(method="cvdt+swap", quality_views=True)
//
// Thin: argument conversion over plugin/gmsh_inprocess.h; C++ errors become Python exceptions
// (cvtmesh.InputError is a ValueError).
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "plugin/gmsh_inprocess.h"
#include "core/io/gmsh_session.h"
#include "core/io/geo_scan.h"
#include "core/pipeline/option_schema.h"
#include "core/pipeline/optimize.h"
#include "core/util/error.h"

namespace py = pybind11;
using namespace cvtmesh;

namespace {

py::object json_loads(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

// The options given as keyword arguments, set by the option schema (core/pipeline/option_schema.h):
// names, types and defaults come from there, and optimize() validates the values, so a bad one is
// refused with the same OptionError (cvtmesh.InputError) as on the CLI and in the GUI panel.
GmshOptimizeOptions options_from(const py::kwargs& kwargs) {
  GmshOptimizeOptions o;
  o.optimize.method = "";  // the dimension's default
  for (const auto& [key, value] : kwargs) {
    const std::string k = py::str(key);
    if (k == "dim") {
      o.dim = value.cast<int>();
    } else if (k == "quality_views") {
      o.quality_views = value.cast<bool>();
    } else if (k == "generate") {
      o.generate = value.cast<bool>();
    } else if (k == "fe_measures") {
      o.fe.mode = value.cast<std::string>();
    } else if (k == "wave_speed") {
      o.fe.wave_speed = value.cast<double>();
    } else if (k == "progress") {
      if (value.is_none()) continue;
      if (!PyCallable_Check(value.ptr())) throw py::type_error("progress must be callable or None");
      py::object progress = py::reinterpret_borrow<py::object>(value);
      o.optimize.progress = [progress](const OptimizeProgress& p) {
        py::dict d;
        d["phase"] = p.phase;
        d["start"] = p.start;
        d["iteration"] = p.iteration;
        d["D"] = p.D;
        d["energy"] = p.energy;
        d["q_min"] = p.q_min;
        d["q_avg"] = p.q_avg;
        progress(d);  // a Python exception raised here aborts the optimization, model unchanged
      };
    } else {
      const OptionSpec* s = find_option(k);
      if (!s || !(s->fronts & kPython) || s->name != k)
        throw py::type_error("optimize() got an unexpected keyword argument '" + k + "'");
      if (py::isinstance<py::str>(value))
        set_text(*s, o.optimize, value.cast<std::string>());
      else if (py::isinstance<py::bool_>(value) || py::isinstance<py::int_>(value) ||
               py::isinstance<py::float_>(value))
        set_number(*s, o.optimize, value.cast<double>());
      else
        throw py::type_error("optimize(): " + k + " must be a number, a bool or a string");
    }
  }
  return o;
}

// The docstring of optimize(), from the schema and the method registry.
std::string optimize_doc() {
  std::string d =
      "optimize(**options) -> dict\n\n"
      "Optimizes the mesh of the current Gmsh model in place: every volume (3D) or every planar\n"
      "surface (2D). Entities, physical groups and lower-dimensional elements stay.\n\n"
      "Front-end arguments:\n"
      "  dim: 2 or 3 (default -1: the highest meshed dimension)\n"
      "  generate: mesh the model first if it has no mesh (default False)\n"
      "  quality_views: add per-element views Q, radius ratio, min angle (default False)\n"
      "  progress: called with a dict (phase, start, iteration, D, energy, q_min, q_avg)\n\n"
      "Options (checked by the core; a bad value raises cvtmesh.InputError):\n";
  for (const OptionSpec& s : option_schema())
    if (s.fronts & kPython) d += "  " + s.name + ": " + describe(s) + "\n";
  d += "\nMethods:\n" + methods_help();
  d += "\nReturns the paper's table as a dict: method, dim, surface_mesh, iterations, converged,\n"
       "seconds, views, before and after (number_of_elements, Q bins, q_min, average_quality, "
       "bad/good %,\n"
       "dihedral/planar angles, average_radius_ratio).";
  return d;
}

}  // namespace

PYBIND11_MODULE(cvtmesh, m) {
  m.doc() =
      "CVT mesh optimization (Du & Wang) of the current Gmsh model of this process.\n"
      "Use with Debian's python3-gmsh: import gmsh, cvtmesh; gmsh.initialize(); gmsh.open(...);\n"
      "gmsh.model.mesh.generate(3); cvtmesh.optimize(method='cvdt+swap').";
  m.attr("__version__") = CVTMESH_VERSION;
  // The Gmsh of this process is Python's (gmsh.initialize()); cvtmesh never initializes or
  // finalizes it. (Gmsh 4.8 cannot be asked whether it is initialized.)
  set_gmsh_initialized_by_caller(true);

  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<OutputError> output_error(m, "OutputError", PyExc_OSError);
  static py::exception<InvariantError> invariant_error(m, "InvariantError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      input_error(e.what());
    } catch (const OutputError& e) {
      output_error(e.what());
    } catch (const InvariantError& e) {
      invariant_error(e.what());
    }
  });

  m.def(
      "methods", [](int dim) { return methods_for_dim(dim); }, py::arg("dim") = 3,
      "The optimization methods available for meshes of dimension dim (2 or 3), in menu order.");

  static const std::string doc = optimize_doc();
  m.def(
      "optimize",
      [](const py::kwargs& kwargs) {
        const GmshOptimizeOptions o = options_from(kwargs);
        return json_loads(gmsh_optimize(o).to_json());
      },
      doc.c_str());

  m.def(
      "options",
      [] {
        py::list out;
        for (const OptionSpec& s : option_schema()) {
          if (!(s.fronts & kPython)) continue;
          py::dict d;
          d["name"] = s.name;
          d["flag"] = s.flag;
          d["default"] = value_text(s, OptimizeOptions{});
          d["help"] = describe(s);
          out.append(d);
        }
        return out;
      },
      "The options of optimize() (the option schema): name, CLI flag, default, help.");

  m.def(
      "scan_geo",
      [](const std::string& path) {
        py::list out;
        for (const GeoScanFinding& f : scan_geo_for_processes(path)) {
          py::dict d;
          d["file"] = f.file;
          d["line"] = f.line;
          d["command"] = f.command;
          d["detail"] = f.detail;
          out.append(d);
        }
        return out;
      },
      py::arg("path"),
      "The commands of a .geo script (and of what it Includes or Merges) that would start a\n"
      "program (SystemCall, NonBlockingSystemCall, OnelabRun, Solver.Executable, or a file name\n"
      "the scan cannot follow): a list of dicts (file, line, command, detail); empty if none.\n"
      "Call it before gmsh.open on a file from someone else (docs/reliability.md, Security).");

  m.def(
      "quality",
      [](int dim, bool quality_views, const std::string& fe, double wave_speed) {
        GmshOptimizeOptions o;
        o.dim = dim;
        o.quality_views = quality_views;
        o.fe.mode = fe;
        o.fe.wave_speed = wave_speed;
        const GmshQualityResult q = gmsh_quality(o);
        QualityTable t;
        t.columns = {q.stats};
        py::dict d = json_loads(t.to_json())[py::int_(0)];
        d["views"] = q.views;
        return d;
      },
      py::kw_only(), py::arg("dim") = -1, py::arg("quality_views") = false,
      py::arg("fe_measures") = "auto", py::arg("wave_speed") = 1.0,
      "Quality statistics of the current model's mesh (unchanged), as one column of the paper's\n"
      "table; quality_views=True also adds the per-element views. The FE measures (time_step,\n"
      "element_time_step, cg_iterations, stiffness_condition; None when not measured):\n"
      "fe_measures='auto' (meshes up to 1000000 elements), 'on' or 'off'; the time steps scale\n"
      "as 1/wave_speed. optimize() takes the same two keywords.");
}
