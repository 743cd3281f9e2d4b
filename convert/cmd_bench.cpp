// cvtmesh bench: speed and memory of our methods next to Gmsh's and TetGen's, on the same inputs,
// in one run. Each measurement runs in a forked child process so that its peak memory (maxrss)
// is its own. Prints a Markdown table (docs/benchmarks.md is made from it).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "convert/cli_common.h"
#include "convert/schema_cli.h"
#include "core/delaunay/delaunay3.h"
#include "bench/baselines/tetgen_optimize.h"
#include "bench/baselines/gmsh_optimizer.h"
#include "bench/baselines/cgal_mesh3.h"
#include "bench/baselines/cgal_remesh.h"
#include "bench/baselines/netgen_optimize.h"
#include "core/pipeline/optimize.h"
#include "core/util/error.h"

namespace cvtmesh::cli {
namespace {

struct Row {
  std::string input, method;
  long nb_tets_in = 0, nb_tets_out = 0;
  double seconds = 0, peak_mb = 0;
  int iterations = 0;
  double q_avg = 0, q_min = 0, min_dihedral = 0, bad_pct = 0;
  double s_per_it = 0;  // Lloyd seconds per iteration (0: no Lloyd phase)
  // The median Lloyd iteration's own time (OptimizeResult::lloyd_iteration_seconds: the
  // steady-state cost, without the phases' set-up and first page faults; 0: no Lloyd phase).
  double s_per_it_median = 0;
  // The FE measures of the output (core/quality/fe_measures.h) and their cost, not in `seconds`.
  bool fe_measured = false;
  double time_step = 0, element_time_step = 0, fe_seconds = 0;
  long cg_iterations = 0;
  std::vector<double> energy;  // Lloyd energy before each iteration
  bool ok = false;
  std::string error;
};

using Clock = std::chrono::steady_clock;

// What a child reports to the parent through the pipe: one JSON object (a Row without the
// labels and the peak memory, which the parent knows), e.g. {"ok":true,"nb_tets_in":24700,...}
// or {"ok":false,"error":"..."}. Doubles keep all their digits (nlohmann_json writes the
// shortest representation that reads back exactly).
nlohmann::json row_to_json(const Row& r) {
  if (!r.ok) return {{"ok", false}, {"error", r.error}};
  return {{"ok", true},
          {"nb_tets_in", r.nb_tets_in},
          {"nb_tets_out", r.nb_tets_out},
          {"seconds", r.seconds},
          {"iterations", r.iterations},
          {"q_avg", r.q_avg},
          {"q_min", r.q_min},
          {"min_dihedral", r.min_dihedral},
          {"bad_pct", r.bad_pct},
          {"s_per_it", r.s_per_it},
          {"s_per_it_median", r.s_per_it_median},
          {"fe_measured", r.fe_measured},
          {"time_step", r.time_step},
          {"element_time_step", r.element_time_step},
          {"cg_iterations", r.cg_iterations},
          {"fe_seconds", r.fe_seconds},
          {"energy", r.energy}};
}

// Fills `row` from a child's report; a report that is not the expected JSON (the child died
// while writing it) leaves row.ok false with the reason in row.error.
void row_from_json(const std::string& text, Row& row) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    row.ok = j.at("ok").get<bool>();
    if (!row.ok) {
      row.error = j.at("error").get<std::string>();
      return;
    }
    row.nb_tets_in = j.at("nb_tets_in").get<long>();
    row.nb_tets_out = j.at("nb_tets_out").get<long>();
    row.seconds = j.at("seconds").get<double>();
    row.iterations = j.at("iterations").get<int>();
    row.q_avg = j.at("q_avg").get<double>();
    row.q_min = j.at("q_min").get<double>();
    row.min_dihedral = j.at("min_dihedral").get<double>();
    row.bad_pct = j.at("bad_pct").get<double>();
    row.s_per_it = j.at("s_per_it").get<double>();
    row.s_per_it_median = j.at("s_per_it_median").get<double>();
    row.fe_measured = j.at("fe_measured").get<bool>();
    row.time_step = j.at("time_step").get<double>();
    row.element_time_step = j.at("element_time_step").get<double>();
    row.cg_iterations = j.at("cg_iterations").get<long>();
    row.fe_seconds = j.at("fe_seconds").get<double>();
    row.energy = j.at("energy").get<std::vector<double>>();
  } catch (const nlohmann::json::exception& e) {
    row.ok = false;
    if (row.error.empty())
      row.error = text.empty() ? "no report" : std::string("bad report: ") + e.what();
  }
}

// Runs job() in a child, which writes its Row as JSON to a pipe (row_to_json). Peak memory from
// wait4.
Row run_isolated(const std::string& input, const std::string& method,
                 const std::function<void(Row&)>& job) {
  Row row;
  row.input = input;
  row.method = method;
  int fd[2];
  if (pipe(fd) != 0) throw std::runtime_error("bench: pipe failed");
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("bench: fork failed");
  if (pid == 0) {
    close(fd[0]);
    Row r;
    try {
      job(r);
      r.ok = true;
    } catch (const std::exception& e) {
      r.ok = false;
      r.error = e.what();
      for (char& c : r.error)
        if (c == '\n') c = ' ';
    }
    const std::string s = row_to_json(r).dump();
    ssize_t w = write(fd[1], s.data(), s.size());
    (void)w;
    close(fd[1]);
    _exit(0);
  }
  close(fd[1]);
  std::string data;
  char buf[4096];
  ssize_t n;
  while ((n = read(fd[0], buf, sizeof buf)) > 0) data.append(buf, static_cast<std::size_t>(n));
  close(fd[0]);
  int status = 0;
  struct rusage ru {};
  wait4(pid, &status, 0, &ru);
  row.peak_mb = ru.ru_maxrss / 1024.0;
  if (!WIFEXITED(status)) row.error = "crashed";
  row_from_json(data, row);
  return row;
}

// The FE options of the run (--fe-measures, --wave-speed), set once before the rows run.
FeOptions& bench_fe() {
  static FeOptions fe;
  return fe;
}

void fill_quality(Row& r, const TetMesh& m) {
  const QualityStats s = quality_stats(m, "");
  r.nb_tets_out = s.nb_elements;
  r.q_avg = s.q_avg;
  r.q_min = s.q_min;
  r.min_dihedral = s.min_angle;
  r.bad_pct = s.bad_pct;
  const FeMeasures fe = fe_measures(m, bench_fe());
  r.fe_measured = fe.measured;
  r.time_step = fe.time_step;
  r.element_time_step = fe.element_time_step;
  r.cg_iterations = fe.cg_iterations;
  r.fe_seconds = fe.seconds;
}

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

struct BenchOpts {
  std::vector<double> sizes = {25000, 100000};
  bool femur = false;
  std::vector<std::string> methods = {"cvdt", "cvdt+swap", "cvdt+swap+smooth", "combined"};
  bool plain = false;
  std::string cache;         // directory of the cached Inits ("" = ~/.cache/cvtmesh/bench)
  bool gmsh_meshing = true;  // the two rows that time Gmsh's meshing
  bool peers = true;         // the TetGen, Netgen and CGAL rows
};

// Where the Init of an input is cached: one binary .msh per model and size parameters.
std::string cache_path(const std::string& dir, const std::string& geo,
                       const std::vector<std::pair<std::string, double>>& numbers) {
  std::string key = std::filesystem::path(geo).stem().string();
  for (const auto& [name, value] : numbers) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "_%s%.6g", name.c_str(), value);
    key += buf;
  }
  return dir + "/" + key + ".msh";
}

std::string default_cache_dir() {
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
    return std::string(x) + "/cvtmesh/bench";
  if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/cvtmesh/bench";
  return std::filesystem::temp_directory_path().string() + "/cvtmesh-bench";
}

}  // namespace

void register_bench(CLI::App& app) {
  auto bo = std::make_shared<BenchOpts>();
  auto opt = std::make_shared<OptimizeOptions>();
  CLI::App* c = app.add_subcommand("bench",
                                   "time and peak memory of our methods, Gmsh's meshing/optimizer "
                                   "and TetGen -q -O on cube_sphere "
                                   "at several sizes (and the femur); prints a Markdown table");
  c->add_option("--sizes", bo->sizes,
                "target numbers of tets of the cube_sphere inputs (default 25000 100000)");
  c->add_flag("--femur", bo->femur, "also the femur (geo/femur.geo)");
  c->add_option("--methods", bo->methods, "our methods to run");
  c->add_flag("--plain-lloyd", bo->plain,
              "also plain Lloyd (the paper's step), and how many iterations of L-BFGS (the "
              "default) and of Anderson-accelerated Lloyd reach its final energy");
  c->add_option("--cache", bo->cache,
                "directory where each input's Init is meshed once and kept (binary .msh; "
                "default ~/.cache/cvtmesh/bench); every row but Gmsh's meshing reads it, untimed");
  c->add_flag_callback(
      "--no-gmsh-meshing", [bo] { bo->gmsh_meshing = false; },
      "skip the rows that time Gmsh's meshing (with and without its optimizer)");
  c->add_flag_callback(
      "--no-peers", [bo] { bo->peers = false; }, "skip the TetGen, Netgen and CGAL rows");
  add_schema_options(c, *opt, {"method"});  // the schema's options (not --method)
  add_fe_options(c, bench_fe());
  commands().push_back(
      {c, [bo, opt] {
         struct Input {
           std::string name, path;
           std::vector<std::pair<std::string, double>> numbers;
         };
         std::vector<Input> inputs;
         const std::string geo = std::string(CVTMESH_SOURCE_DIR) + "/geo/";
         for (double n : bo->sizes) {
           // ~24.7k tets at h = 0.065, h_ball = 0.05; #tets ~ h^-3.
           const double s = std::cbrt(24700.0 / n);
           inputs.push_back({"cube_sphere ~" + std::to_string(static_cast<long>(n / 1000)) + "k",
                             geo + "cube_sphere.geo",
                             {{"h", 0.065 * s}, {"h_ball", 0.05 * s}}});
         }
         if (bo->femur) inputs.push_back({"femur", geo + "femur.geo", {}});
         std::vector<Row> rows;
         const std::string cache_dir = bo->cache.empty() ? default_cache_dir() : bo->cache;
         std::error_code ec;
         std::filesystem::create_directories(cache_dir, ec);
         if (ec)
           throw OutputError("bench: cannot create the cache directory '" + cache_dir +
                             "': " + ec.message());
         for (const auto& in : inputs) {
           ReadOptions init_ro;
           init_ro.gmsh_optimize = false;
           init_ro.set_numbers = in.numbers;
           ReadOptions gmsh_ro = init_ro;
           gmsh_ro.gmsh_optimize = true;
           // The Init, meshed once (in a child: Gmsh's state stays out of this process) and cached.
           const std::string init_path = cache_path(cache_dir, in.path, in.numbers);
           if (!std::filesystem::exists(init_path)) {
             info() << "cvtmesh: bench: meshing " << in.name << " into " << init_path << "\n";
             const Row made = run_isolated(in.name, "cache", [&](Row& r) {
               MeshData d = read_mesh(in.path, init_ro);
               WriteOptions w;
               w.binary = true;
               write_mesh(d, init_path, w);
               r.nb_tets_in = d.tet.nb_tets();
             });
             if (!made.ok) throw InputError("bench: cannot mesh " + in.path + ": " + made.error);
           }
           auto read_init = [&init_path] { return read_mesh(init_path, ReadOptions{}); };
           // Gmsh: meshing alone (the Init), and meshing with its default optimizer.
           if (bo->gmsh_meshing) {
             rows.push_back(run_isolated(in.name, "Gmsh mesh (no optimizer) = Init", [&](Row& r) {
               const auto t0 = Clock::now();
               MeshData d = read_mesh(in.path, init_ro);
               r.seconds = since(t0);
               r.nb_tets_in = d.tet.nb_tets();
               fill_quality(r, d.tet);
             }));
             rows.push_back(run_isolated(in.name, "Gmsh mesh + Mesh.Optimize", [&](Row& r) {
               const auto t0 = Clock::now();
               MeshData d = read_mesh(in.path, gmsh_ro);
               r.seconds = since(t0);
               r.nb_tets_in = d.tet.nb_tets();
               fill_quality(r, d.tet);
             }));
           }
           // A row that times `op` on the cached Init (op returns its own time, or < 0 to be
           // timed here) and reports its iteration count.
           auto timed_row = [&](const std::string& label, int iterations,
                                const std::function<double(TetMesh&)>& op) {
             rows.push_back(run_isolated(in.name, label, [&](Row& r) {
               MeshData d = read_init();
               r.nb_tets_in = d.tet.nb_tets();
               const auto t0 = Clock::now();
               const double own = op(d.tet);
               r.seconds = own >= 0 ? own : since(t0);
               r.iterations = iterations;
               fill_quality(r, d.tet);
             }));
           };
           if (bo->peers) {
             timed_row("TetGen -q -O on Init", 9, [](TetMesh& m) {
               tetgen_optimize(m);
               return -1.0;
             });
             // The peers a user would pick instead (issue 17): Netgen's volume optimizer (its own
             // time, the transfer to its Python module not counted) and CGAL's remeshing.
             timed_row("Netgen optimize on Init", 1, [](TetMesh& m) {
               const NetgenResult res = netgen_optimize(m);
               if (!res.available) throw std::runtime_error(res.message);
               return res.seconds;
             });
             timed_row("CGAL remeshing on Init", CgalRemeshOptions{}.iterations, [](TetMesh& m) {
               cgal_remesh(m);
               return -1.0;
             });
             timed_row("CGAL Mesh_3 from the Init's surface", 1, [](TetMesh& m) {
               cgal_mesh3(m);
               return -1.0;
             });
           }
           // One constrained Delaunay tetrahedralization of the Init's points by TetGen: what a
           // Lloyd iteration that rebuilt the mesh would pay for its re-insertion alone.
           timed_row("TetGen CDT of the Init's points", 1, [](TetMesh& m) {
             Delaunay3::create("tetgen")->retetrahedralize(m);
             return -1.0;
           });
           auto run_method = [&](const std::string& label, const std::string& m, double omega,
                                 int anderson, int max_it = -1, double tol = -1, int lbfgs = -1) {
             rows.push_back(run_isolated(in.name, label, [&](Row& r) {
               MeshData d = read_init();
               r.nb_tets_in = d.tet.nb_tets();
               OptimizeOptions o = *opt;
               o.method = m;
               o.progress = nullptr;
               o.never_worse = false;  // the method itself is timed, not a fallback
               if (omega > 0) o.relaxation = omega;
               if (anderson >= 0) o.anderson_depth = anderson;
               if (lbfgs >= 0) o.lbfgs_memory = lbfgs;
               if (max_it >= 0) o.max_iterations = max_it;
               if (tol >= 0) o.tolerance = tol;
               const OptimizeResult res = optimize(d, o);
               r.seconds = res.seconds;
               r.iterations = res.iterations;
               r.energy = res.lloyd_energy;
               if (!res.lloyd_energy.empty())
                 r.s_per_it = res.seconds_lloyd / static_cast<double>(res.lloyd_energy.size());
               if (!res.lloyd_iteration_seconds.empty()) {
                 std::vector<double> its = res.lloyd_iteration_seconds;
                 std::nth_element(its.begin(), its.begin() + its.size() / 2, its.end());
                 r.s_per_it_median = its[its.size() / 2];
               }
               fill_quality(r, d.tet);
             }));
           };
           for (const auto& m : bo->methods) run_method(m + " on Init", m, -1, -1);
           if (bo->plain) {
             // Plain Lloyd to convergence, then the accelerated ones (L-BFGS, the 3D default, and
             // over-relaxed Lloyd + Anderson) for as many iterations without a stop (their D
             // criterion differs), to see when they reach that energy.
             run_method("cvdt, plain Lloyd (omega 1, no Anderson)", "cvdt", 1.0, 0, -1, -1, 0);
             const int plain_its = rows.back().ok ? static_cast<int>(rows.back().energy.size()) : 0;
             if (plain_its > 0) {
               run_method("cvdt, L-BFGS (default), as many iterations", "cvdt", -1, -1, plain_its,
                          0.0);
               run_method("cvdt, Anderson (omega 1.5, depth 5), as many iterations", "cvdt", -1, -1,
                          plain_its, 0.0, 0);
             }
           }
           info() << "cvtmesh: bench " << in.name << " done\n";
         }
         std::printf(
             "| input | method | tets in | tets out | seconds | s / Lloyd it | median Lloyd it s | "
             "peak MB | iterations | avg Q | Q_min | min dihedral | bad %% | time step | element "
             "time step | CG its | FE measures s |\n");
         std::printf(
             "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
             "\n");
         for (const auto& r : rows) {
           if (!r.ok) {
             std::printf("| %s | %s | failed: %s ||||||||||||||\n", r.input.c_str(),
                         r.method.c_str(), r.error.c_str());
             continue;
           }
           char spi[32] = "-";
           if (r.s_per_it > 0) std::snprintf(spi, sizeof spi, "%.3f", r.s_per_it);
           char med[32] = "-";
           if (r.s_per_it_median > 0) std::snprintf(med, sizeof med, "%.3f", r.s_per_it_median);
           char fe[128] = "- | - | - | -";
           if (r.fe_measured)
             std::snprintf(fe, sizeof fe, "%.3e | %.3e | %ld | %.2f", r.time_step,
                           r.element_time_step, r.cg_iterations, r.fe_seconds);
           std::printf(
               "| %s | %s | %ld | %ld | %.2f | %s | %s | %.0f | %d | %.4f | %.4f | %.2f | %.2f | "
               "%s "
               "|\n",
               r.input.c_str(), r.method.c_str(), r.nb_tets_in, r.nb_tets_out, r.seconds, spi, med,
               r.peak_mb, r.iterations, r.q_avg, r.q_min, r.min_dihedral, r.bad_pct, fe);
         }
         // Accelerated vs plain Lloyd: iterations to reach the plain run's final energy.
         if (bo->plain) {
           std::printf(
               "\n| input | plain Lloyd: iterations, final energy | accelerated run | iterations "
               "to "
               "reach it (1e-6 rel.) | ratio |\n|---|---|---|---|---:|\n");
           for (const auto& p : rows) {
             if (!p.ok || p.method.rfind("cvdt, plain", 0) != 0 || p.energy.empty()) continue;
             const double target = p.energy.back() * (1 + 1e-6);
             for (const auto& a : rows) {
               if (!a.ok || a.input != p.input ||
                   a.method.find(", as many iterations") == std::string::npos)
                 continue;
               int reached = -1;
               for (std::size_t i = 0; i < a.energy.size() && reached < 0; ++i)
                 if (a.energy[i] <= target) reached = static_cast<int>(i) + 1;
               char rs[64] = "not reached";
               if (reached > 0) std::snprintf(rs, sizeof rs, "%d of %zu", reached, a.energy.size());
               std::printf("| %s | %zu, %.9g | %s | %s | %s |\n", p.input.c_str(), p.energy.size(),
                           p.energy.back(), a.method.substr(0, a.method.find(", as many")).c_str(),
                           rs,
                           reached > 0 ? std::to_string(static_cast<double>(reached) /
                                                        static_cast<double>(p.energy.size()))
                                             .substr(0, 5)
                                             .c_str()
                                       : "-");
             }
           }
         }
         return 0;
       }});
}

}  // namespace cvtmesh::cli
