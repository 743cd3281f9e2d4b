// cvtmesh compare IN: the paper's Table 6/7 — Init | CombOpt | CVDT | CVDT+SWAP — plus Gmsh's own
// optimizer and TetGen's -O on the same Init, with iterations and seconds.
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>

#include "convert/cli_common.h"
#include "core/delaunay/tetgen_optimize.h"
#include "core/io/gmsh_optimizer.h"
#include "core/pipeline/optimize.h"
#include "core/pipeline/verify_mesh.h"
#include "core/util/error.h"

namespace cvtmesh::cli {

ReadOptions init_read_options(const InputOpts& in);
void add_method_options(CLI::App* c, OptimizeOptions& o);

namespace {

struct CompareOpts {
  std::string format = "text";
  std::string save_dir;
  bool baselines = true;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

void register_compare(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  auto opt = std::make_shared<OptimizeOptions>();
  auto co = std::make_shared<CompareOpts>();
  CLI::App* c = app.add_subcommand("compare",
                                   "the paper's table: Init | CombOpt | CVDT | CVDT+SWAP | Gmsh "
                                   "optimize | TetGen -O on the same Init");
  add_input(c, *in);
  add_method_options(c, *opt);
  c->add_option("--format", co->format, "text, markdown or json")
      ->check(CLI::IsMember({"text", "markdown", "json"}));
  c->add_option("--save", co->save_dir,
                "also write every mesh (with quality views) into this directory");
  c->add_flag("!--no-baselines", co->baselines, "skip Gmsh's and TetGen's optimizers");
  commands().push_back(
      {c, [in, opt, co] {
         const auto t0 = std::chrono::steady_clock::now();
         const MeshData init = read_mesh(in->path, init_read_options(*in));
         const double mesh_seconds = seconds_since(t0);
         if (init.dim != 3) throw InputError("compare: needs a 3D tetrahedral mesh");
         QualityTable table;
         auto save = [&](const MeshData& d, const std::string& name) {
           if (co->save_dir.empty()) return;
           WriteOptions w;
           w.fields = quality_fields(d);
           write_mesh(d, co->save_dir + "/" + name + ".msh", w);
         };
         QualityStats s0 = quality_stats(init.tet, "Init");
         s0.extra.push_back({"seconds", mesh_seconds});
         table.columns.push_back(s0);
         save(init, "init");
         struct Col {
           std::string method, label, file;
         };
         const std::vector<Col> cols = {{"combined", "CombOpt", "combopt"},
                                        {"cvdt", "CVDT", "cvdt"},
                                        {"cvdt+swap", "CVDT+SWAP", "cvdt_swap"}};
         const auto available = methods_for_dim(3);
         for (const auto& col : cols) {
           if (std::find(available.begin(), available.end(), col.method) == available.end())
             continue;
           MeshData d = init;
           OptimizeOptions o = *opt;
           o.method = col.method;
           o.progress = nullptr;
           const OptimizeResult r = optimize(d, o);
           QualityStats s = r.after;
           s.label = col.label;
           s.extra.push_back({"iterations", static_cast<double>(r.iterations)});
           s.extra.push_back({"seconds", r.seconds});
           table.columns.push_back(s);
           save(d, col.file);
           std::cerr << "cvtmesh: " << col.label << " done (" << r.seconds << " s)\n";
         }
         if (co->baselines) {
           {
             MeshData d = init;
             const auto t1 = std::chrono::steady_clock::now();
             gmsh_optimize_mesh(d, "", 1);
             const double sec = seconds_since(t1);
             verify_optimized(init.tet, d.tet);
             QualityStats s = quality_stats(d.tet, "Gmsh optimize");
             s.extra.push_back({"iterations", 1});
             s.extra.push_back({"seconds", sec});
             table.columns.push_back(s);
             save(d, "gmsh_optimize");
           }
           {
             MeshData d = init;
             const auto t1 = std::chrono::steady_clock::now();
             tetgen_optimize(d.tet);
             const double sec = seconds_since(t1);
             verify_optimized(init.tet, d.tet);
             QualityStats s = quality_stats(d.tet, "TetGen -q -O");
             s.extra.push_back({"iterations", 9});
             s.extra.push_back({"seconds", sec});
             table.columns.push_back(s);
             save(d, "tetgen_O");
           }
         }
         std::cout << render(table, co->format);
         return 0;
       }});
}

}  // namespace cvtmesh::cli
