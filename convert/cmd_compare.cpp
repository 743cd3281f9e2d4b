// cvtmesh compare IN: the paper's Table 6/7 — Init | CombOpt | CVDT | CVDT+SWAP — plus our
// CVDT+SWAP+smooth and Gmsh's and TetGen's own optimizers on the same Init, with iterations and
// seconds.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <utility>

#include "convert/cli_common.h"
#include "convert/schema_cli.h"
#include "bench/baselines/tetgen_optimize.h"
#include "bench/baselines/gmsh_optimizer.h"
#include "bench/baselines/cgal_mesh3.h"
#include "bench/baselines/cgal_remesh.h"
#include "bench/baselines/netgen_optimize.h"
#include "core/mesh/check_surface_mesh.h"
#include "core/io/histogram_png.h"
#include "core/io/histogram_svg.h"
#include "core/quality/quality_fields.h"
#include "core/quality/quality_histogram.h"
#include "core/pipeline/optimize.h"
#include "core/pipeline/verify_mesh.h"
#include "core/util/error.h"

namespace cvtmesh::cli {

ReadOptions init_read_options(const InputOpts& in);

namespace {

struct CompareOpts {
  std::string format = "text";
  std::string save_dir;
  bool baselines = true;
  FeOptions fe;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Comparison {
  const OptimizeOptions& opt;
  const CompareOpts& co;
  const MeshData& init;
  QualityTable table;
  std::vector<QualityHistogram> histograms;  // one per column, written by --save

  void save(const MeshData& d, const std::string& name) const {
    if (co.save_dir.empty()) return;
    WriteOptions w;
    w.fields = quality_fields(d);
    w.policy.force = true;  // --save refreshes its own directory
    // Binary: every column exactly as it was measured (its runs are verified in full precision;
    // a CVDT column may hold slivers that 16 printed digits would flatten: Gmsh's t13).
    w.binary = true;
    write_mesh(d, co.save_dir + "/" + name + ".msh", w);
  }

  // verified = false: the run checked its own (free-boundary) invariants.
  void add(const MeshData& d, const std::string& label, const std::string& file, int iterations,
           double seconds, bool verify = true) {
    if (verify) verify_optimized(init.tet, d.tet);
    QualityStats s = quality_stats(d.tet, label);
    add_fe_measures(s, d, co.fe);
    s.extra.push_back({"iterations", static_cast<double>(iterations)});
    s.extra.push_back({"seconds", seconds});
    table.columns.push_back(s);
    histograms.push_back(quality_histogram(element_qualities(d.tet, Measure::kQ), 20, label));
    save(d, file);
    info() << "cvtmesh: " << label << " done (" << seconds << " s)\n";
  }

  // Runs `method` on a copy of `from`; the column's cost adds that of the run it continues.
  std::pair<double, int> run(const MeshData& from, const std::string& method,
                             const std::string& label, const std::string& file,
                             double seconds_before, int iterations_before, MeshData& out) {
    out = from;
    OptimizeOptions o = opt;
    o.method = method;
    o.progress = nullptr;
    // The paper's columns show each method's own result (CVDT alone is worse than Init at its
    // worst tet, the paper's point): no never-worse fallback here.
    o.never_worse = false;
    // Verified in full precision and saved in binary (save): without the never-worse fallback a
    // method's slivers would otherwise stop the comparison.
    o.output_digits = 0;
    const OptimizeResult r = optimize(out, o);
    const int its = iterations_before > 0 ? iterations_before : r.iterations;
    add(out, label, file, its, seconds_before + r.seconds);
    return {seconds_before + r.seconds, its};
  }
};

}  // namespace

void register_compare(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  auto opt = std::make_shared<OptimizeOptions>();
  auto co = std::make_shared<CompareOpts>();
  CLI::App* c =
      app.add_subcommand("compare",
                         "the paper's table: Init | CombOpt | CVDT | CVDT+SWAP (| "
                         "CVDT+SWAP+smooth | Gmsh optimize | TetGen -q -O | Netgen | CGAL) on "
                         "the same Init");
  add_input(c, *in);
  add_schema_options(c, *opt);
  c->add_option("--format", co->format, "text, markdown or json")
      ->check(CLI::IsMember({"text", "markdown", "json"}));
  c->add_option("--save", co->save_dir,
                "also write every mesh (with quality views) and the columns' quality histograms "
                "(histogram.svg, and histogram.png when rsvg-convert is installed) into this "
                "directory");
  c->add_flag_callback(
      "--no-baselines", [co] { co->baselines = false; },
      "skip the peers: Gmsh's, TetGen's, Netgen's and CGAL's optimizers");
  add_fe_options(c, co->fe);
  commands().push_back(
      {c, [in, opt, co] {
         if (!co->save_dir.empty()) {
           std::error_code ec;
           std::filesystem::create_directories(co->save_dir, ec);
           if (ec)
             throw OutputError("cannot create the directory '" + co->save_dir +
                               "': " + ec.message());
         }
         load_sizing_reference(*opt, *in);
         const auto t0 = std::chrono::steady_clock::now();
         const MeshData init = read_mesh(in->path, init_read_options(*in));
         const double mesh_seconds = seconds_since(t0);
         if (init.dim != 3) throw InputError("compare: needs a 3D tetrahedral mesh");
         if (is_surface_mesh(init.tet))
           throw InputError("compare: needs a 3D tetrahedral mesh; '" + in->path +
                            "' is a surface mesh in space (no tetrahedra): `cvtmesh optimize` "
                            "optimizes it");
         Comparison cmp{*opt, *co, init, {}};
         QualityStats s0 = quality_stats(init.tet, "Init");
         add_fe_measures(s0, init, co->fe);
         s0.extra.push_back({"seconds", mesh_seconds});
         cmp.table.columns.push_back(s0);
         cmp.histograms.push_back(
             quality_histogram(element_qualities(init.tet, Measure::kQ), 20, "Init"));
         cmp.save(init, "init");
         // The paper's methods compose: CVDT+SWAP = SWAP applied to the CVDT.
         MeshData comb, cvdt, cvdt_swap, polished;
         cmp.run(init, "combined", "CombOpt", "combopt", 0, 0, comb);
         const auto [t1, i1] = cmp.run(init, "cvdt", "CVDT", "cvdt", 0, 0, cvdt);
         const auto [t2, i2] = cmp.run(cvdt, "swap", "CVDT+SWAP", "cvdt_swap", t1, i1, cvdt_swap);
         cmp.run(cvdt_swap, "smooth", "CVDT+SWAP+smooth", "cvdt_swap_smooth", t2, i2, polished);
         // The default pipeline with a free boundary (issue 13), unless --fix-boundary.
         if (!opt->fix_boundary) {
           MeshData free_b = init;
           OptimizeOptions o = *opt;
           o.method = "cvdt+swap+smooth";
           o.progress = nullptr;
           const OptimizeResult r = optimize(free_b, o);
           cmp.add(free_b, "free boundary", "cvdt_swap_smooth_free", r.iterations, r.seconds,
                   false);
         }
         if (co->baselines) {
           MeshData g = init;
           auto t = std::chrono::steady_clock::now();
           try {
             gmsh_optimize_mesh(g, "", 1);
             cmp.add(g, "Gmsh optimize", "gmsh_optimize", 1, seconds_since(t));
           } catch (const InvariantError& e) {
             // Gmsh 4.8's optimizer moves boundary vertices of some discrete surfaces (MMG's
             // torus): reported, the other columns kept.
             info() << "cvtmesh: Gmsh optimize baseline left out: " << e.what() << "\n";
           }
           MeshData tg = init;
           t = std::chrono::steady_clock::now();
           try {
             tetgen_optimize(tg.tet);
             cmp.add(tg, "TetGen -q -O", "tetgen_q_O", 9, seconds_since(t));
           } catch (const InvariantError& e) {
             // A baseline that breaks the boundary is reported, not fatal for the comparison.
             info() << "cvtmesh: TetGen -q -O baseline left out: " << e.what() << "\n";
           }
           // Netgen's and CGAL's optimizers may remove or add interior vertices: their columns
           // are checked by verify_peer (valid mesh, the same boundary triangles).
           MeshData ng = init;
           try {
             const NetgenResult r = netgen_optimize(ng.tet);
             if (r.available)
               cmp.add(ng, "Netgen optimize", "netgen_optimize", 1, r.seconds, false);
             else
               info() << "cvtmesh: Netgen baseline left out: " << r.message << "\n";
           } catch (const InvariantError& e) {
             info() << "cvtmesh: Netgen baseline left out: " << e.what() << "\n";
           }
           MeshData cg = init;
           t = std::chrono::steady_clock::now();
           try {
             cgal_remesh(cg.tet);
             cmp.add(cg, "CGAL remeshing", "cgal_remesh", 1, seconds_since(t), false);
           } catch (const InvariantError& e) {
             info() << "cvtmesh: CGAL remeshing baseline left out: " << e.what() << "\n";
           }
           // CGAL's Mesh_3 makes a new mesh with a new surface from the Init's boundary: not an
           // optimizer of this mesh, the peer a user could mesh with instead (one region only).
           MeshData m3 = init;
           t = std::chrono::steady_clock::now();
           try {
             cgal_mesh3(m3.tet);
             cmp.add(m3, "CGAL Mesh_3 (new surface)", "cgal_mesh3", 1, seconds_since(t), false);
           } catch (const InvariantError& e) {
             info() << "cvtmesh: CGAL Mesh_3 baseline left out: " << e.what() << "\n";
           }
         }
         if (!co->save_dir.empty()) {
           OutputPolicy p;
           p.force = true;
           write_histogram_svg(cmp.histograms, co->save_dir + "/histogram.svg", p);
           // The same picture as PNG when Debian's rsvg-convert is there (it is optional here).
           if (!histogram_png_rasterizer().empty())
             write_histogram_png(cmp.histograms, co->save_dir + "/histogram.png", p);
           else
             info() << "cvtmesh: histogram.png left out: rsvg-convert (librsvg2-bin) not found\n";
         }
         std::cout << render(cmp.table, co->format);
         return 0;
       }});
}

}  // namespace cvtmesh::cli
