// cvtmesh-gui [options] [model.geo|model.msh|...] [-- gmsh options]
// The Gmsh GUI with a "Mesh optimization (CVT)" group in its ONELAB tree. Run optimizes the model
// loaded in the GUI (meshing it first if needed) in a worker thread, replaces its mesh, adds
// quality views, and shows the results in the tree; progress goes to the status bar and errors to
// the message console. Thin: parsing, the event loop and rendering; the work is in core/.
#include <atomic>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/geometry/boundary_geometry.h"
#include "core/io/atomic_file.h"
#include "core/io/gmsh_cad_boundary.h"
#include "core/quality/quality_stats.h"
#include "core/quality/quality_histogram.h"
#include "core/util/error.h"
#include "plugin/gmsh_gui.h"
#include "plugin/gmsh_inprocess.h"
#include "plugin/panel.h"
#include "plugin/stale_watch.h"
#include "core/util/wait_policy.h"

namespace {

using namespace cvtmesh;

const std::string kRun = "cvtmesh-run";
const std::string kStop = "cvtmesh-stop";
const std::string kDone = "cvtmesh-done";
const std::string kQuality = "cvtmesh-quality";

struct Args {
  std::string model;
  plugin::PanelPreset preset;
  bool show_quality = false;
  bool run_on_start = false;
  bool allow_system_calls = false;
  std::string result_json;
  std::optional<double> exit_after_run;
  std::vector<std::string> gmsh_args;
};

// The command line: options through CLI11; what follows the first "--" goes to Gmsh unread.
// Returns the exit status to stop with (help printed: 0, bad command line: 2), or -1 to go on.
int parse(int argc, char** argv, Args& a) {
  a.gmsh_args.push_back(argv[0]);
  int ours = argc;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--") {
      ours = i;
      a.gmsh_args.insert(a.gmsh_args.end(), argv + i + 1, argv + argc);
      break;
    }
  CLI::App app(
      "Opens MODEL (.geo, .msh, or anything Gmsh opens) in the Gmsh GUI with a\n"
      "'Mesh optimization (CVT)' group in the ONELAB tree; its Run button optimizes the mesh.",
      "cvtmesh-gui");
  app.footer(
      "GMSH-OPTIONS after -- go to Gmsh: cvtmesh-gui [OPTIONS] [MODEL] -- GMSH-OPTIONS...\n"
      "(e.g. -- -setnumber h 0.1).");
  app.add_option("model", a.model, "the model to open");
  app.add_option("--method", a.preset.method,
                 "initial method (see the panel; e.g. cvdt+swap, combined)");
  app.add_option("--max-iterations", a.preset.max_iterations, "initial max iterations");
  app.add_option("--tolerance", a.preset.tolerance, "initial tolerance");
  app.add_option("--sizing", a.preset.sizing, "initial sizing: mesh or uniform");
  app.add_flag_callback(
      "--no-quality-views", [&a] { a.preset.quality_views = 0; },
      "do not add quality views after a run");
  app.add_flag("--show-quality", a.show_quality,
               "show the quality of the model's mesh on start (meshing it if needed)");
  app.add_flag("--run-on-start", a.run_on_start, "press Run once the window is up");
  app.add_flag("--allow-system-calls", a.allow_system_calls,
               "let MODEL (a .geo and what it includes) run programs (SystemCall, OnelabRun); "
               "refused by default, with the file, line and command in the message console");
  app.add_option("--result-json", a.result_json,
                 "after each action, write its outcome to FILE (JSON: {\"action\": "
                 "\"optimize\"|\"quality\"|\"stale\", \"result\"|\"stopped\"|\"error\"|"
                 "\"changed\": ..., \"display\": the views and the cut})")
      ->option_text("FILE");
  double exit_after = 0;
  CLI::Option* exit_opt =
      app.add_option("--exit-after-run", exit_after,
                     "close the window S seconds (default 0) after the first run; the exit "
                     "status is 0 if the run succeeded, 1 if not (a value after it is S: give "
                     "MODEL before)")
          ->expected(0, 1)
          ->option_text("[S]");
  try {
    app.parse(ours, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return 0;
  } catch (const CLI::ParseError& e) {
    std::cerr << "cvtmesh-gui: " << e.what() << " (Gmsh options go after --; see --help)\n";
    return 2;
  }
  if (exit_opt->count() > 0) a.exit_after_run = exit_after;
  return -1;
}

// The optimization running in its worker thread, and what it leaves behind.
struct Job {
  std::thread thread;
  std::atomic<bool> cancel{false};
  GmshOptimizeOptions options;
  MeshData data;
  OptimizeResult result;
  std::string error;     // empty: success
  bool stopped = false;  // Stop was pressed: a notice, not an error
  bool running = false;
};

struct Cancelled {};

// The CAD geometry of the model in the GUI, queried from the worker thread: every Gmsh call under
// the GUI lock (the event loop holds it except while it waits).
class LockedGeometry final : public BoundaryGeometry {
 public:
  explicit LockedGeometry(std::shared_ptr<const BoundaryGeometry> g) : g_(std::move(g)) {}
  bool closest_on_surface(int s, const double* p, double* q) const override {
    GuiLock lock;
    return g_->closest_on_surface(s, p, q);
  }
  bool closest_on_curve(int c, const double* p, double* q) const override {
    GuiLock lock;
    return g_->closest_on_curve(c, p, q);
  }
  double distance_to_boundary(const double* p) const override {
    GuiLock lock;
    return g_->distance_to_boundary(p);
  }
  std::vector<double> samples() const override { return g_->samples(); }
  const char* kind() const override { return g_->kind(); }
  bool thread_safe() const override { return false; }

 private:
  std::shared_ptr<const BoundaryGeometry> g_;
};

BoundaryModel locked_cad_boundary(const TetMesh& mesh, const BoundaryModelOptions& options) {
  BoundaryModel b;
  {
    GuiLock lock;
    b = make_gmsh_cad_boundary_if_cad(mesh, options);
  }
  if (b.geometry) b.geometry = std::make_shared<LockedGeometry>(b.geometry);
  return b;
}

class App {
 public:
  explicit App(const Args& args) : args_(args) {}

  int run() {
    define(args_.preset);
    gui_set_button("Run", kRun);
    gui_start(300);
    // Start-up actions, one at a time (ONELAB/Action holds a single action).
    if (args_.show_quality) pending_.push_back(kQuality);
    if (args_.run_on_start) pending_.push_back(kRun);
    while (gui_wait(0.25)) {
      if (exit_at_ && elapsed() >= *exit_at_) break;
      watch_stale();
      std::string action = gui_take_action();
      if (action.empty() && !pending_.empty() && !job_.running) {
        action = pending_.front();
        pending_.erase(pending_.begin());
      }
      if (action == kRun || action == kDone) action_ = "optimize";
      if (action == kQuality) action_ = "quality";
      try {
        if (action == kRun)
          start();
        else if (action == kStop)
          job_.cancel = true;
        else if (action == kDone)
          finish();
        else if (action == kQuality)
          show_quality();
        else if (action == "reset")
          define({});
        else if (!job_.running && gui_model_dim() != dim_ && gui_model_dim() > 0)
          define({});
      } catch (const std::exception& e) {
        report_error(std::string("cvtmesh: ") + e.what());
      } catch (...) {
        report_error("cvtmesh: unexpected error");
      }
    }
    if (job_.thread.joinable()) {
      job_.cancel = true;
      job_.thread.join();
    }
    return exit_status_;
  }

 private:
  void define(const plugin::PanelPreset& preset) {
    dim_ = gui_model_dim();
    plugin::define_panel(tree_, dim_ == 2 ? 2 : 3, preset);
    plugin::define_quality_button(tree_, kQuality);
    gui_refresh();
  }

  void start() {
    if (job_.running) return;
    job_.options = plugin::read_panel(tree_);
    job_.options.generate = true;
    tree_.progress("cvtmesh: reading the mesh...");
    job_.data = gmsh_read_current(job_.options);  // meshes the model first if it has no mesh
    gui_refresh();
    job_.cancel = false;
    job_.stopped = false;
    job_.error.clear();
    job_.running = true;
    job_.options.optimize.boundary_model = locked_cad_boundary;  // the model's CAD, if any
    const int max_it = job_.options.optimize.max_iterations;
    job_.options.optimize.progress = [this, max_it](const OptimizeProgress& p) {
      if (job_.cancel) throw Cancelled{};
      {
        GuiLock lock;
        tree_.progress(plugin::progress_text(p, max_it));
      }
      gui_awake();
    };
    tree_.info("cvtmesh: optimizing with " + job_.options.optimize.method + "...");
    write_json("optimize", "status", "running");
    gui_set_button("Stop", kStop);
    gui_refresh();
    job_.thread = std::thread([this] {
      try {
        job_.result = optimize(job_.data, job_.options.optimize);
      } catch (const Cancelled&) {
        job_.stopped = true;
      } catch (const std::exception& e) {
        job_.error = std::string("cvtmesh: ") + e.what();
      } catch (...) {
        job_.error = "cvtmesh: the optimization failed";
      }
      GuiLock lock;
      gui_post_action(kDone);
    });
  }

  void finish() {
    if (!job_.running) return;
    job_.thread.join();
    job_.running = false;
    gui_set_button("Run", kRun);
    if (job_.stopped) {  // the user's choice: a notice in the console, not an error
      const std::string m = "cvtmesh: stopped; the mesh was left unchanged";
      tree_.info(m);
      tree_.progress(m);
      write_json("optimize", "stopped", m);
      gui_refresh();
      ran(1);
      return;
    }
    if (!job_.error.empty()) {
      report_error(job_.error);
      return;
    }
    tree_.progress("cvtmesh: writing the optimized mesh back...");
    const GmshOptimizeResult r = gmsh_write_back(job_.data, job_.result, job_.options);
    plugin::show_results(tree_, r);
    int graph = 0;
    if (!r.views.empty()) {
      // The histogram of the result as a graph; Q over its own range, cut.
      graph = gui_add_histogram_view({histogram(job_.data, "after")}, kHistogramViewName);
      gui_show_view(r.views.front(), 0, 0, true);
      watch_.arm(options_signature());
    }
    gui_refresh();
    tree_.info(plugin::summary(r));
    tree_.progress(plugin::summary(r));
    auto result = nlohmann::ordered_json::parse(r.to_json());
    result["histogram_view"] = graph;
    write_json("optimize", "result", result);
    ran(0);
  }

  void show_quality() {
    GmshOptimizeOptions o = plugin::read_panel(tree_);
    o.generate = true;
    o.quality_views = true;
    const GmshQualityResult q = gmsh_quality(o);
    int graph = 0;
    if (!q.views.empty()) {
      const MeshData current = gmsh_read_current(o);
      graph = gui_add_histogram_view({histogram(current, "current")}, kHistogramViewName);
      gui_show_view(q.views.front(), 0, 0, true);
      watch_.arm(options_signature());
    }
    gui_refresh();
    char buf[300];
    std::snprintf(buf, sizeof buf,
                  "cvtmesh: current mesh: %ld elements, Q avg %.4f, Q min %.4f, bad %.2f%%",
                  q.stats.nb_elements, q.stats.q_avg, q.stats.q_min, q.stats.bad_pct);
    if (q.stats.fe_measured)
      std::snprintf(buf + std::strlen(buf), sizeof buf - std::strlen(buf),
                    ", time step %.3e (element bound %.3e), CG iterations %ld", q.stats.time_step,
                    q.stats.element_time_step, q.stats.cg_iterations);
    tree_.info(buf);
    tree_.progress(buf);
    QualityTable t;
    t.columns = {q.stats};
    auto result = nlohmann::ordered_json::parse(t.to_json()).at(0);
    result["views"] = q.views;
    result["histogram_view"] = graph;
    write_json("quality", "result", result);
  }

  static QualityHistogram histogram(const MeshData& d, const std::string& label) {
    return quality_histogram(
        d.dim == 3 ? element_qualities(d.tet, Measure::kQ) : element_qualities(d.tri, Measure::kQ),
        20, label);
  }

  // The panel's options as text; a value the schema refuses counts as a change too.
  std::string options_signature() {
    try {
      return plugin::panel_signature(plugin::read_panel(tree_));
    } catch (const std::exception& e) {
      return std::string("invalid: ") + e.what();
    }
  }

  // Once a second while the views of a run are shown: a changed mesh or changed options mark
  // them stale (their names end in " (stale)").
  void watch_stale() {
    if (job_.running || !watch_.armed() || elapsed() < next_watch_) return;
    next_watch_ = elapsed() + 1.0;
    const std::string what = watch_.check(options_signature());
    if (what.empty()) return;
    const std::string m = "cvtmesh: the " + what +
                          " changed since the quality was shown: its views are marked (stale)";
    tree_.info(m);
    tree_.progress(m);
    write_json("stale", "changed", what);
  }

  void report_error(const std::string& message) {
    tree_.error(message);
    write_json(action_, "error", message);
    gui_refresh();
    ran(1);
  }

  void ran(int status) {
    if (!args_.exit_after_run || exit_at_) return;
    exit_status_ = status;
    exit_at_ = elapsed() + *args_.exit_after_run;
  }

  void write_json(const std::string& action, const std::string& key,
                  const nlohmann::ordered_json& value) {
    if (args_.result_json.empty()) return;
    nlohmann::ordered_json j;
    j["action"] = action;
    j[key] = value;
    try {
      j["display"] = nlohmann::ordered_json::parse(gui_display_json());
    } catch (...) {
    }
    // Written whole under a temporary name, then renamed: a watcher never sees half a file.
    try {
      AtomicFile f(args_.result_json);
      {
        std::ofstream out(f.temp_path());
        out << j.dump(2) << "\n";
        if (!out) throw OutputError("cannot write '" + f.temp_path() + "'");
      }
      f.commit();
    } catch (const std::exception& e) {
      tree_.error(std::string("cvtmesh: ") + e.what());
    }
  }

  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }

  const Args& args_;
  LocalOnelab tree_;
  Job job_;
  plugin::StaleWatch watch_;
  double next_watch_ = 0;
  int dim_ = -1;
  std::vector<std::string> pending_;
  std::string action_ = "optimize";  // what an error is reported against
  int exit_status_ = 0;
  std::optional<double> exit_at_;
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

}  // namespace

int main(int argc, char** argv) {
  cvtmesh::prefer_passive_openmp_threads(argv);
  Args args;
  if (const int stop = parse(argc, argv, args); stop >= 0) return stop;
  try {
    gui_initialize(args.gmsh_args);
  } catch (const std::exception& e) {
    std::cerr << "cvtmesh-gui: " << e.what() << "\n";
    return 2;
  }
  int status = 0;
  try {
    // An unreadable model is reported in the message console; the GUI still opens.
    if (!args.model.empty()) {
      try {
        gui_open(args.model, args.allow_system_calls);
      } catch (const std::exception& e) {
        LocalOnelab().error(std::string("cvtmesh: ") + e.what());
      }
    }
    App app(args);
    status = app.run();
  } catch (const std::exception& e) {
    std::cerr << "cvtmesh-gui: " << e.what() << "\n";
    status = 2;
  } catch (...) {
    std::cerr << "cvtmesh-gui: unexpected error\n";
    status = 2;
  }
  gui_finalize();
  return status;
}
