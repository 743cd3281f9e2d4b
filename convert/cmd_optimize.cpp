// cvtmesh optimize IN -o OUT [--method M] [the options of core/pipeline/option_schema.h].
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "convert/cli_common.h"
#include "convert/json_report.h"
#include "convert/limits.h"
#include "convert/progress_display.h"
#include "convert/schema_cli.h"
#include "core/io/gmsh_cad_boundary.h"
#include "core/io/gmsh_mid_edge_projector.h"
#include "core/io/place_mid_edge_nodes.h"
#include "core/io/read_mesh.h"
#include "core/mesh/transfer_views.h"
#include "core/io/gmsh_session.h"
#include "core/distributed/optimize_partitioned.h"
#include "core/pipeline/option_schema.h"
#include "core/pipeline/optimize.h"

namespace cvtmesh::cli {

namespace {

// `optimize --parts P`: the partitioned optimization (core/distributed/), the parts on the ranks
// of exchange_factory() (this process alone, or MPI's under cvtmesh-mpi). Rank 0 reads, prints
// and writes; the other ranks get their parts from it (their `d` is empty). An error on rank 0
// (a refused input) ends its process, and cvtmesh-mpi then aborts the others.
void run_partitioned(MeshData& d, OptimizeOptions& opt, const PartitionOptions& po,
                     PartExchange& ex, const std::string& path) {
  if (ex.rank() == 0 && d.dim != 3)
    throw InputError("optimize --parts: '" + path +
                     "' is not a 3D tet mesh (the partitioned optimization needs one)");
  if (ex.rank() == 0 && d.tet.nb_tets() < po.parts)
    throw InputError("optimize --parts " + std::to_string(po.parts) + ": '" + path + "' has " +
                     std::to_string(d.tet.nb_tets()) + " tets, fewer than the parts");
  if (!opt.fix_boundary && ex.rank() == 0 && opt.method == "cvdt+swap+smooth")
    info() << "cvtmesh: note: in the partitioned optimization the boundary moves on the input's "
              "own triangles (not on a CAD model), without surface coarsening\n";
  const PartitionedResult r = optimize_partitioned(d.tet, opt, po, ex);
  if (ex.rank() != 0) return;
  for (std::size_t k = 0; k < r.rounds.size(); ++k) {
    const PartitionRound& pr = r.rounds[k];
    std::string sizes;
    for (int n : pr.part_tets) sizes += (sizes.empty() ? "" : ", ") + std::to_string(n);
    char line[256];
    std::snprintf(line, sizeof line,
                  "round %zu: %zu parts (%s tets), %d interface vertices, %d cut faces (%d on "
                  "the previous interface), %.2f s, Q_min %.4f, avg %.4f\n",
                  k + 1, pr.part_tets.size(), sizes.c_str(), pr.nb_interface, pr.nb_cut_faces,
                  pr.nb_avoided_cut, pr.seconds, pr.after.q_min, pr.after.q_avg);
    info() << line;
  }
  info() << "cvtmesh: " << r.nb_frozen_every_round
         << " interior vertices were frozen (on an interface) in every round\n";
  for (const auto& note : r.notes) info() << "cvtmesh: note: " << note << "\n";
  if (global_opts().quiet) return;
  QualityTable t;
  QualityStats before = r.before, after = r.after;
  before.label = "input";
  after.label = opt.method + " x " + std::to_string(po.parts) + " parts";
  after.extra.push_back({"rounds", static_cast<double>(po.rounds)});
  after.extra.push_back({"seconds", r.seconds});
  t.columns = {before, after};
  std::cerr << t.to_text();
}

}  // namespace

void register_optimize(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  auto out = std::make_shared<OutputOpts>();
  auto opt = std::make_shared<OptimizeOptions>();
  auto strict = std::make_shared<bool>(false);
  auto report = std::make_shared<std::string>();
  auto format = std::make_shared<std::string>("text");
  auto partition = std::make_shared<PartitionOptions>();
  partition->parts = 0;
  CLI::App* c = app.add_subcommand(
      "optimize", "optimize a mesh (CVT/Lloyd CVDT, sliver swaps, classical baselines)");
  add_input(c, *in);
  c->add_option("-o,--output", out->path, "output file (format by extension)")->required();
  add_output_flags(c, *out);
  add_schema_options(c, *opt);
  // Not in the schema (a list of names): the free boundary's locked physical groups.
  c->add_option("--lock-physical", opt->lock_physical,
                "free boundary: keep the surfaces / curves of this physical group (by name) fixed; "
                "repeatable");
  c->add_option("--report", *report,
                "also write the result as JSON to this file (docs/cli.md, JSON: before, after, "
                "method, iterations, ...)");
  c->add_option("--format", *format,
                "text: the quality table on stderr; json: the JSON report on stdout as well")
      ->check(CLI::IsMember({"text", "json"}));
  c->add_flag("--strict", *strict,
              "exit with code 6 (after writing the output) when the method stopped at the "
              "iteration cap, fell back to local operations, or the input was kept");
  c->add_option("--parts", partition->parts,
                "partitioned optimization (docs/scaling.md): cut the tets into this many parts "
                "(METIS), optimize each alone with its interface and the boundary fixed, put "
                "them back; under `mpirun -n P cvtmesh-mpi` the parts run on the P ranks")
      ->check(CLI::Range(1, 1 << 20));
  c->add_option("--rounds", partition->rounds,
                "partitioned optimization: rounds of cut, optimize, merge, each cutting away "
                "from the previous interfaces (default 2)")
      ->check(CLI::Range(1, 100));
  c->add_flag_callback(
      "--allow-worse", [opt] { opt->never_worse = false; },
      "keep the method's result even if its Q_min or dihedral angles are worse than the "
      "input's (default: fall back to the polish alone, or keep the input)");
  commands().push_back(
      {c, [in, out, opt, strict, report, format, partition] {
         // The ranks of a partitioned run; only rank 0 prints and writes.
         const std::unique_ptr<PartExchange> ranks =
             partition->parts > 0 ? exchange_factory()() : nullptr;
         if (ranks && ranks->rank() != 0) global_opts().quiet = true;
         const bool quiet = global_opts().quiet;
         // The progress lines (convert/progress_display.h): the one place they are drawn.
         auto progress = std::make_shared<ProgressDisplay>(ProgressDisplay::for_stderr());
         // On an error, the line being drawn is cleared before the message (the callback below
         // keeps the display alive past this scope).
         struct EndProgress {
           std::shared_ptr<ProgressDisplay> p;
           ~EndProgress() { p->finish(); }
         } end_progress{progress};
         // A bad value or reference fails before the (possibly long) read of the input.
         if (sizing_is_path(*opt)) progress->begin("reading", "sizing reference " + opt->sizing);
         load_sizing_reference(*opt, *in);
         validate(*opt, 0);
         // A model Gmsh meshes here (.geo, .step, .brep, ...) keeps its CAD while this session
         // lives: a free boundary then moves on the CAD entities themselves (a .msh or a surface
         // file has none: the discrete geometry of the input).
         // An order-2 model's mid-edge nodes are projected on that CAD as well.
         // In a partitioned run only rank 0 reads (the others get their parts from it).
         const bool writer = !ranks || ranks->rank() == 0;
         std::optional<GmshSession> cad;
         const bool model = writer && read_mesh_meshes_a_model(in->path);
         if (model) {
           cad.emplace();
           if (!opt->fix_boundary) opt->boundary_model = make_gmsh_cad_boundary_if_cad;
         }
         MeshData d;
         if (writer) {
           progress->begin(model ? "meshing" : "reading", in->path);
           d = read_mesh(in->path, in->to_read_options());
           progress->finish();
           for (const auto& note : d.model().read_notes)
             info() << "cvtmesh: note: " << note << "\n";
         }
         // A bad output location fails now, not after the optimization.
         if (writer) check_can_write(out->path, out->to_write_options(d, in->path));
         if (writer && !report->empty()) check_directory_writable(*report);
         if (ranks) {
           if (!report->empty() || *format == "json")
             throw InputError(
                 "optimize --parts: --report and --format json are not available "
                 "for the partitioned optimization");
           if (writer && !d.model().views.empty()) {
             info() << "cvtmesh: note: the input's views are not carried through the "
                       "partitioned optimization: not written\n";
             d.model().views.clear();
           }
           run_partitioned(d, *opt, *partition, *ranks, in->path);
           if (writer && d.model().high_order.order == 2) {
             const MidEdgePlacement& p =
                 place_mid_edge_nodes(d, cad ? gmsh_cad_mid_edge_projector() : MidEdgeProjector{});
             info() << "cvtmesh: note: " << mid_edge_summary(p) << "\n";
           }
           cad.reset();
           if (!writer) return kExitOk;
           progress->begin("writing", out->path);
           const WriteReport written = write_mesh(d, out->path, out->to_write_options(d, in->path));
           progress->done();
           for (const auto& note : written.notes) info() << "cvtmesh: note: " << note << "\n";
           info() << "cvtmesh: wrote " << out->path << " (" << partition->parts << " parts, "
                  << partition->rounds << " rounds)\n";
           return kExitOk;
         }
         // -q draws nothing: no callback, so the core skips the quality summary it computes for
         // each Lloyd iteration's report (~5 % of the Lloyd phase's CPU at 1M tets).
         if (!progress->quiet())
           opt->progress = [progress](const OptimizeProgress& p) { progress->update(p); };
         // --time-limit: optimize starts no optional run that would not fit (a fifth of what is
         // left kept for writing).
         if (const double left = seconds_left(); std::isfinite(left))
           opt->time_budget = std::max(0.0, 0.8 * left);
         // The input's views ($NodeData, $ElementData) stay out of the pipeline's copies; they
         // are carried onto the result afterwards.
         MeshData input_mesh;
         if (!d.model().views.empty()) {
           input_mesh = d;
           d.model().views.clear();
         }
         // A refusal from inside the optimizer names the file it was about.
         OptimizeResult r = [&] {
           try {
             return optimize(d, *opt);
           } catch (const InputError& e) {
             const std::string what = e.what();
             if (what.rfind("'" + in->path + "'", 0) == 0) throw;
             throw InputError("'" + in->path + "': " + what);
           }
         }();
         if (input_mesh.dim && !input_mesh.model().views.empty()) {
           d.model().views = transfer_views(input_mesh, d);
           input_mesh = MeshData{};
           r.notes.push_back(
               std::to_string(d.model().views.size()) +
               " view(s) of the input carried onto the optimized mesh (node values "
               "interpolated linearly, element values from the input's element "
               "holding the centroid)" +
               (file_extension(out->path) == ".msh"
                    ? std::string()
                    : "; only a .msh output holds them: not written to " + out->path));
         }
         // Order 2: the mid-edge nodes of the optimized corner mesh, on the CAD where there is one.
         if (d.model().high_order.order == 2) {
           const MidEdgePlacement& p =
               place_mid_edge_nodes(d, cad ? gmsh_cad_mid_edge_projector() : MidEdgeProjector{});
           r.notes.push_back(mid_edge_summary(p));
         }
         cad.reset();  // the writer starts from a clean Gmsh
         opt->boundary_model = nullptr;
         opt->progress = nullptr;
         progress->begin("writing", out->path);
         const WriteReport written = write_mesh(d, out->path, out->to_write_options(d, in->path));
         progress->done();
         r.notes.insert(r.notes.end(), written.notes.begin(), written.notes.end());
         QualityTable t;
         QualityStats before = r.before, after = r.after;
         before.label = "input";
         after.label = r.method;
         after.extra.push_back({"iterations", static_cast<double>(r.iterations)});
         after.extra.push_back({"seconds", r.seconds});
         t.columns = {before, after};
         if (!quiet) std::cerr << t.to_text();
         if (!quiet && r.boundary_free)
           std::fprintf(stderr,
                        "free boundary: %s geometry, %d surface, %d curve, %d fixed vertices; "
                        "%d vertices moved, Hausdorff %.3e (%.2e of the diagonal, "
                        "bound %.3e), volume change %.4f %%, worst boundary triangle Q %.4f -> "
                        "%.4f\n",
                        r.boundary_geometry.c_str(), r.nb_surface_vertices, r.nb_curve_vertices,
                        r.nb_fixed_vertices, r.nb_boundary_moved, r.hausdorff,
                        r.hausdorff / r.diagonal, r.hausdorff_tolerance, 100 * r.volume_change,
                        r.tri_q_min_before, r.tri_q_min_after);
         if (!quiet && r.boundary_free && r.nb_boundary_removed > 0) {
           const std::string folds = r.nb_folds_removed > 0
                                         ? " (" + std::to_string(r.nb_folds_removed) +
                                               " of them the input's surface folds)"
                                         : "";
           std::fprintf(stderr, "surface coarsening: %d surface vertices removed%s\n",
                        r.nb_boundary_removed, folds.c_str());
         }
         for (const auto& note : r.notes) info() << "cvtmesh: note: " << note << "\n";
         const bool capped = !r.converged && !r.kept_input;
         if (capped)
           info() << "cvtmesh: warning: '" << r.method << "' stopped at the iteration cap ("
                  << r.iterations << " iterations) before converging; raise --max-iterations "
                  << "or --tolerance\n";
         if (!report->empty() || *format == "json") {
           const std::string json =
               optimize_json(r, opt->method, in->path, out->path).dump(2) + "\n";
           if (*format == "json") std::cout << json;
           if (!report->empty()) write_text_file(*report, json);
         }
         info() << "cvtmesh: wrote " << out->path << " (" << r.method << ", " << r.iterations
                << " iterations, " << (r.converged ? "converged" : "not converged")
                << (r.kept_input ? ", input kept unchanged" : "") << ")\n";
         const bool fell_back = r.kept_input || r.method != opt->method;
         return *strict && (capped || fell_back) ? kExitStrict : kExitOk;
       }});
}

}  // namespace cvtmesh::cli
