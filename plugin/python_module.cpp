// The Python module `cvtmesh`: optimizes the current model of the Gmsh loaded in the same Python
// process (Debian's python3-gmsh loads libgmsh.so.4.8; this module links the same library, so both
// see one Gmsh).
//
//   import gmsh, cvtmesh
//   gmsh.initialize(); gmsh.open("cube_sphere.geo"); gmsh.model.mesh.generate(3)
//   table = cvtmesh.optimize(method="cvdt+swap", quality_views=True)
//
// Thin: argument conversion over core/io/gmsh_inprocess.h; C++ errors become Python exceptions
// (cvtmesh.InputError is a ValueError).
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "core/io/gmsh_inprocess.h"
#include "core/io/gmsh_session.h"
#include "core/pipeline/optimize.h"
#include "core/util/error.h"

namespace py = pybind11;
using namespace cvtmesh;

namespace {

py::object json_loads(const std::string& text) {
  return py::module_::import("json").attr("loads")(text);
}

// The Lloyd acceleration and minimiser knobs of OptimizeOptions.
struct Acceleration {
  int anderson = OptimizeOptions{}.anderson_depth;
  int lbfgs = OptimizeOptions{}.lbfgs_memory;
  int hops = OptimizeOptions{}.hops;
  double hop_amount = OptimizeOptions{}.hop_amount;
};

GmshOptimizeOptions options_from(const std::string& method, int max_iterations, double tolerance,
                                 double relaxation, const Acceleration& acc,
                                 const std::string& sizing, unsigned seed, int dim,
                                 bool quality_views, bool generate, const py::object& progress) {
  GmshOptimizeOptions o;
  o.optimize.method = method;
  o.optimize.max_iterations = max_iterations;
  o.optimize.tolerance = tolerance;
  o.optimize.relaxation = relaxation;
  if (acc.anderson < 0 || acc.lbfgs < -1 || acc.hops < 0 || !(acc.hop_amount > 0))
    throw py::value_error(
        "anderson and hops must be >= 0, lbfgs >= 0 (or -1: the default), hop_amount > 0");
  o.optimize.anderson_depth = acc.anderson;
  o.optimize.lbfgs_memory = acc.lbfgs;
  o.optimize.hops = acc.hops;
  o.optimize.hop_amount = acc.hop_amount;
  o.optimize.sizing = sizing;
  o.optimize.seed = seed;
  o.dim = dim;
  o.quality_views = quality_views;
  o.generate = generate;
  if (!progress.is_none()) {
    if (!PyCallable_Check(progress.ptr()))
      throw py::type_error("progress must be callable or None");
    o.optimize.progress = [progress](const OptimizeProgress& p) {
      py::dict d;
      d["phase"] = p.phase;
      d["iteration"] = p.iteration;
      d["D"] = p.D;
      d["energy"] = p.energy;
      d["q_min"] = p.q_min;
      d["q_avg"] = p.q_avg;
      progress(d);  // a Python exception raised here aborts the optimization, model unchanged
    };
  }
  return o;
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

  m.def(
      "optimize",
      [](const std::string& method, int max_iterations, double tolerance, double relaxation,
         int anderson, int lbfgs, int hops, double hop_amount, const std::string& sizing,
         unsigned seed, int dim, bool quality_views, bool generate, const py::object& progress) {
        const auto o = options_from(method, max_iterations, tolerance, relaxation,
                                    Acceleration{anderson, lbfgs, hops, hop_amount}, sizing, seed,
                                    dim, quality_views, generate, progress);
        return json_loads(gmsh_optimize(o).to_json());
      },
      py::kw_only(), py::arg("method") = "",
      py::arg("max_iterations") = OptimizeOptions{}.max_iterations,
      py::arg("tolerance") = OptimizeOptions{}.tolerance,
      py::arg("relaxation") = OptimizeOptions{}.relaxation,
      py::arg("anderson") = OptimizeOptions{}.anderson_depth,
      py::arg("lbfgs") = OptimizeOptions{}.lbfgs_memory, py::arg("hops") = OptimizeOptions{}.hops,
      py::arg("hop_amount") = OptimizeOptions{}.hop_amount,
      py::arg("sizing") = OptimizeOptions{}.sizing, py::arg("seed") = 0u, py::arg("dim") = -1,
      py::arg("quality_views") = false, py::arg("generate") = false,
      py::arg("progress") = py::none(),
      "Optimizes the mesh of the current Gmsh model in place: every volume (3D) or every planar\n"
      "surface (2D) with method (one of methods(dim); '' = the first, the paper's best) —\n"
      "dim=-1 picks the highest meshed dimension. Entities, physical groups and\n"
      "lower-dimensional elements stay. relaxation: Lloyd over-relaxation in (0, 2); anderson:\n"
      "Anderson depth; lbfgs: L-BFGS memory (minimise the CVT energy by L-BFGS instead of\n"
      "Lloyd's step; 0 = Lloyd's step, -1 = default: 5 in 3D, 0 in 2D; the paper's plain Lloyd\n"
      "is lbfgs=0, anderson=0, relaxation=1); hops, hop_amount: 2D basin hopping. generate=True "
      "meshes the model first if it has no mesh;\n"
      "quality_views=True adds per-element views (Q, radius ratio, min angle). progress, if\n"
      "given, is called with a dict (phase, iteration, D, energy, q_min, q_avg).\n"
      "Returns the paper's table as a dict: method, dim, iterations, converged, seconds, views,\n"
      "before and after (number_of_elements, Q bins, q_min, average_quality, bad/good %,\n"
      "dihedral/planar angles, average_radius_ratio).");

  m.def(
      "quality",
      [](int dim, bool quality_views) {
        GmshOptimizeOptions o;
        o.dim = dim;
        o.quality_views = quality_views;
        const GmshQualityResult q = gmsh_quality(o);
        QualityTable t;
        t.columns = {q.stats};
        py::dict d = json_loads(t.to_json())[py::int_(0)];
        d["views"] = q.views;
        return d;
      },
      py::kw_only(), py::arg("dim") = -1, py::arg("quality_views") = false,
      "Quality statistics of the current model's mesh (unchanged), as one column of the paper's\n"
      "table; quality_views=True also adds the per-element views.");
}
