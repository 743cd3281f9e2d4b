// Reproduces the 2D experiments of Du & Wang (Section 3, Tables 1-5, Figures 1-7): the regular
// quad and the graded washer, perturbed by RandPert and ClusPert, then optimized by DL, WDL and
// CVT (Lloyd). Prints the tables (Markdown) and the convergence measures, writes SVG pictures.
//
//   build/bench/reproduce_2d --out docs/img/2d > tables.md
//
// Not a test: a documented driver for docs/reproduction-2d.md (timings are printed here only).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <string>

#include "convert/schema_cli.h"
#include "core/pipeline/option_schema.h"
#include "core/util/error.h"
#include "core/cvt/lloyd_optimize_2d.h"
#include "core/io/read_mesh.h"
#include "core/io/svg_io.h"
#include "core/mesh/check_mesh.h"
#include "core/pipeline/perturb2d.h"
#include "core/quality/quality_stats.h"
#include "core/smoothing/dl_optimize_2d.h"
#include "core/smoothing/wdl_optimize_2d.h"

using namespace cvtmesh;

namespace {

struct Run {
  TriMesh2 mesh;
  QualityStats stats;
  int iterations = 0;
  bool converged = false;
  double seconds = 0;
  Lloyd2dReport report;  // CVT only
};

// Distance from each vertex of a to the nearest vertex of b, divided by the local size h(x):
// the largest value, and the fraction of vertices within `tol`.
struct Match {
  double max_rel = 0, frac_close = 0;
};
Match match(const TriMesh2& a, const TriMesh2& b, const std::function<double(const double*)>& h,
            double tol) {
  Match m;
  int close = 0;
  for (int i = 0; i < a.nb_vertices(); ++i) {
    double best = std::numeric_limits<double>::infinity();
    for (int j = 0; j < b.nb_vertices(); ++j)
      best =
          std::min(best, std::hypot(a.point(i)[0] - b.point(j)[0], a.point(i)[1] - b.point(j)[1]));
    const double rel = best / h(a.point(i));
    m.max_rel = std::max(m.max_rel, rel);
    if (rel <= tol) ++close;
  }
  m.frac_close = a.nb_vertices() ? static_cast<double>(close) / a.nb_vertices() : 1;
  return m;
}

std::string row(const char* name, double a, double b, const char* fmt) {
  char buf[160];
  char fa[32], fb[32];
  std::snprintf(fa, sizeof fa, fmt, a);
  std::snprintf(fb, sizeof fb, fmt, b);
  std::snprintf(buf, sizeof buf, "| %-16s | %8s | %8s |\n", name, fa, fb);
  return buf;
}

std::string table(const std::string& caption, const QualityStats& r, const QualityStats& c) {
  std::string s = caption + "\n\n| | RandPert | ClusPert |\n|---|---:|---:|\n";
  s += row("average quality", r.q_avg, c.q_avg, "%.4f");
  s += row("minimum quality", r.q_min, c.q_min, "%.4f");
  s += row("minimum angle", r.min_angle, c.min_angle, "%.2f");
  s += row("maximum angle", r.max_angle, c.max_angle, "%.2f");
  return s + "\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Reproduce Du & Wang's 2D experiments (Tables 1-5, Figures 1-7)"};
  std::string out_dir;
  int quad_n = 12;
  double h0 = 0.08, g = 0.08, r0 = 1.0, r1 = 2.5;
  unsigned seed = 1;
  // The CVT knobs are the option schema's (core/pipeline/option_schema.h) with this driver's
  // reproduction settings: the paper's plain Lloyd step, run far (5000 iterations, D < 1e-10),
  // basin-hopping seed 1 (--hop-seed; --seed is RandPert's here).
  OptimizeOptions cvt;
  apply_preset("plain (paper)", cvt);
  cvt.max_iterations = 5000;
  cvt.tolerance = 1e-10;
  cvt.seed = 1;
  app.add_option("--out", out_dir, "directory for the SVG pictures (none if empty)");
  app.add_option("--quad-n", quad_n, "quad: divisions per side (geo/quad.geo n)");
  app.add_option("--washer-h0", h0, "washer: size at the inner circle (geo/washer.geo h0)");
  app.add_option("--washer-g", g, "washer: size gradient (geo/washer.geo g)");
  app.add_option("--seed", seed, "RandPert seed");
  std::vector<std::string> methods = {"dl", "wdl", "cvt"}, examples = {"quad", "washer"};
  app.add_option("--methods", methods, "methods to run (dl, wdl, cvt)");
  app.add_option("--examples", examples, "examples to run (quad, washer)");
  app.add_option("--washer-r1", r1, "washer: outer radius (geo/washer.geo r1)");
  double rand_amount = -1, clus_amount = -1;
  cli::add_schema_options(&app, cvt,
                          {"method", "seed", "sizing", "swap_below", "polish_flip_below",
                           "polish_q_floor", "polish_maxmin", "polish_repair"});
  app.add_option("--hop-seed", cvt.seed, "CVT: basin-hopping random seed (default 1)");
  app.add_option("--random-amount", rand_amount, "RandPert amount (default: perturb_2d's)");
  app.add_option("--cluster-amount", clus_amount, "ClusPert amount (default: perturb_2d's)");
  CLI11_PARSE(app, argc, argv);
  try {
    validate(cvt, 2);
  } catch (const InputError& e) {
    std::fprintf(stderr, "reproduce_2d: %s\n", e.what());
    return 2;
  }
  const OptimizeOptions o2 = resolve(cvt, 2);
  const int max_it = o2.max_iterations;
  const double tol = o2.tolerance;
  auto wanted = [](const std::vector<std::string>& v, const std::string& x) {
    return std::find(v.begin(), v.end(), x) != v.end();
  };
  if (!out_dir.empty()) std::filesystem::create_directories(out_dir);

  const std::string src = CVTMESH_SOURCE_DIR;
  auto svg = [&](const TriMesh2& m, const std::string& name, const std::string& title) {
    if (!out_dir.empty())
      write_svg(m, out_dir + "/" + name + ".svg", {.width = 640, .q_low = 0.5, .title = title});
  };

  struct Example {
    std::string name, title;
    MeshData initial;
    SizingField2dOptions sizing;
    std::function<double(const double*)> h;
  };
  std::vector<Example> ex(2);
  ex[0].name = "quad";
  ex[0].title = "quad";
  ex[0].initial =
      read_mesh(src + "/geo/quad.geo", {.dim = 2, .set_numbers = {{"n", double(quad_n)}}});
  ex[0].sizing.kind = "uniform";
  ex[0].sizing.h = 1.0 / quad_n;
  ex[0].h = [=](const double*) { return 1.0 / quad_n; };
  ex[1].name = "washer";
  ex[1].title = "washer";
  ex[1].initial =
      read_mesh(src + "/geo/washer.geo",
                {.dim = 2, .set_numbers = {{"h0", h0}, {"g", g}, {"r0", r0}, {"r1", r1}}});
  ex[1].h = [=](const double* x) { return h0 + g * (std::hypot(x[0], x[1]) - r0); };
  ex[1].sizing.kind = "function";
  ex[1].sizing.function = ex[1].h;

  std::string md;
  char buf[512];
  for (Example& e : ex) {
    if (!wanted(examples, e.name)) continue;
    const TriMesh2& init = e.initial.tri;
    std::snprintf(buf, sizeof buf, "### %s: %d vertices, %d triangles\n\n", e.name.c_str(),
                  init.nb_vertices(), init.nb_tris());
    md += buf;
    svg(init, e.name + "_initial", e.title + ": initial mesh (Gmsh)");
    std::map<std::string, TriMesh2> pert;
    for (const char* p : {"randpert", "cluspert"}) {
      TriMesh2 m = init;
      Perturb2dOptions po;
      po.kind = std::string(p) == "randpert" ? Perturbation2d::kRandom : Perturbation2d::kCluster;
      po.seed = seed;
      po.amount = po.kind == Perturbation2d::kRandom ? rand_amount : clus_amount;
      perturb_2d(m, po);
      svg(m, e.name + "_" + p,
          e.title + ": " + (po.kind == Perturbation2d::kRandom ? "RandPert" : "ClusPert"));
      pert[p] = m;
    }
    md += table("Initial (Gmsh) and perturbed meshes (columns: RandPert, ClusPert; initial: " +
                    std::to_string(quality_stats(init, "").q_avg).substr(0, 6) + " avg Q)",
                quality_stats(pert["randpert"], ""), quality_stats(pert["cluspert"], ""));
    std::map<std::string, Run> runs;
    for (const char* method : {"dl", "wdl", "cvt"})
      for (const char* p : {"randpert", "cluspert"}) {
        if (!wanted(methods, method)) continue;
        Run r;
        r.mesh = pert[p];
        LloydOptions loop{.max_iterations = max_it, .tolerance = tol};
        const auto t0 = std::chrono::steady_clock::now();
        LloydResult lr;
        if (std::string(method) == "cvt") {
          lr = lloyd_optimize_2d(r.mesh,
                                 {.lloyd = loop,
                                  .sizing = e.sizing,
                                  .relaxation = o2.relaxation,
                                  .anderson_depth = o2.anderson_depth,
                                  .lbfgs_memory = o2.lbfgs_memory,
                                  .hops = o2.hops,
                                  .hop_amount = o2.hop_amount,
                                  .hop_seed = o2.seed},
                                 nullptr, &r.report);
        } else {
          Smooth2dOptions so;
          so.loop = loop;
          so.sizing = e.sizing;
          lr = std::string(method) == "dl" ? dl_optimize_2d(r.mesh, so)
                                           : wdl_optimize_2d(r.mesh, so);
        }
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!r.report.hop_energies.empty()) {
          std::fprintf(stderr, "%s %s hops: Lloyd F %.8e;", e.name.c_str(), p,
                       r.report.lloyd_energy);
          for (double f : r.report.hop_energies) std::fprintf(stderr, " %.8e", f);
          std::fprintf(stderr, "\n");
        }
        r.iterations = lr.iterations;
        r.converged = lr.converged;
        if (!check_mesh(r.mesh).ok)
          std::fprintf(stderr, "INVALID MESH %s %s %s\n", e.name.c_str(), method, p);
        r.stats = quality_stats(r.mesh, "");
        const std::string up = std::string(method) == "cvt"  ? "CVT"
                               : std::string(method) == "dl" ? "DL"
                                                             : "WDL";
        const bool hopped = std::string(method) == "cvt" && o2.hops > 0;
        svg(r.mesh, e.name + "_" + method + (hopped ? "_hops_" : "_") + p,
            e.title + ": " + up + (hopped ? " + basin hopping" : "") + " from " +
                (std::string(p) == "randpert" ? "RandPert" : "ClusPert"));
        runs[std::string(method) + "_" + p] = std::move(r);
      }
    for (const char* method : {"dl", "wdl", "cvt"}) {
      if (!wanted(methods, method)) continue;
      const Run& a = runs[std::string(method) + "_randpert"];
      const Run& b = runs[std::string(method) + "_cluspert"];
      const std::string up = std::string(method) == "cvt"  ? "CVT"
                             : std::string(method) == "dl" ? "DL"
                                                           : "WDL";
      md += table("**" + e.name + ", " + up + "**", a.stats, b.stats);
      std::snprintf(buf, sizeof buf, "iterations %d / %d (converged: %s / %s), %.1f s / %.1f s\n\n",
                    a.iterations, b.iterations, a.converged ? "yes" : "no",
                    b.converged ? "yes" : "no", a.seconds, b.seconds);
      md += buf;
      if (std::string(method) == "cvt") {
        std::snprintf(buf, sizeof buf,
                      "CVT energy F: Lloyd %.8e / %.8e (%d / %d iterations); final %.8e / %.8e "
                      "(hops accepted %d of %d / %d of %d)\n\n",
                      a.report.lloyd_energy, b.report.lloyd_energy, a.report.lloyd_iterations,
                      b.report.lloyd_iterations, a.report.energy, b.report.energy,
                      a.report.hops_accepted, a.report.hops, b.report.hops_accepted, b.report.hops);
        md += buf;
      }
      const Match ab = match(a.mesh, b.mesh, e.h, 0.05);
      std::snprintf(buf, sizeof buf,
                    "RandPert vs ClusPert result: largest distance from a vertex to the nearest "
                    "vertex of the other mesh %.3g h; %.1f%% of the vertices within 0.05 h\n\n",
                    ab.max_rel, 100 * ab.frac_close);
      md += buf;
      if (e.name == "quad")
        for (const Run* r : {&a, &b}) {
          const Match m = match(r->mesh, init, e.h, 0.05);
          std::snprintf(buf, sizeof buf,
                        "%s result vs the regular mesh: largest distance %.3g h; %.1f%% of the "
                        "vertices within 0.05 h\n\n",
                        r == &a ? "RandPert" : "ClusPert", m.max_rel, 100 * m.frac_close);
          md += buf;
        }
    }
  }
  std::cout << md;
  return 0;
}
