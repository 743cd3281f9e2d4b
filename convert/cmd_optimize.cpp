// cvtmesh optimize IN -o OUT [--method M] [the options of core/pipeline/option_schema.h].
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "convert/cli_common.h"
#include "convert/schema_cli.h"
#include "core/io/gmsh_cad_boundary.h"
#include "core/io/gmsh_session.h"
#include "core/pipeline/option_schema.h"
#include "core/pipeline/optimize.h"

namespace cvtmesh::cli {

void register_optimize(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  auto out = std::make_shared<OutputOpts>();
  auto opt = std::make_shared<OptimizeOptions>();
  auto quiet = std::make_shared<bool>(false);
  auto strict = std::make_shared<bool>(false);
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
  c->add_flag("-q,--quiet", *quiet, "no progress on stderr");
  c->add_flag("--strict", *strict,
              "exit with code 6 (after writing the output) when the method stopped at the "
              "iteration cap, fell back to local operations, or the input was kept");
  c->add_flag("!--allow-worse", opt->never_worse,
              "keep the method's result even if its Q_min or dihedral angles are worse than the "
              "input's (default: fall back to the polish alone, or keep the input)");
  commands().push_back(
      {c, [in, out, opt, quiet, strict] {
         validate(*opt, 0);  // a bad value fails before the (possibly long) read
         // A model Gmsh meshes here (.geo, .step, .brep, ...) keeps its CAD while this session
         // lives: a free boundary then moves on the CAD entities themselves (a .msh or a surface
         // file has none: the discrete geometry of the input).
         std::optional<GmshSession> cad;
         if (!opt->fix_boundary && read_mesh_meshes_a_model(in->path)) {
           cad.emplace();
           opt->boundary_model = make_gmsh_cad_boundary_if_cad;
         }
         MeshData d = read_mesh(in->path, in->to_read_options());
         // A bad output location fails now, not after the optimization.
         check_can_write(out->path, out->to_write_options(d, in->path));
         if (!*quiet)
           opt->progress = [](const OptimizeProgress& p) {
             std::fprintf(stderr, "%-9s it %4d%s D %.3e  energy %.6e  Q_min %.4f  Q_avg %.4f",
                          p.phase.c_str(), p.iteration, p.restarted ? "*" : " ", p.D, p.energy,
                          p.q_min, p.q_avg);
             if (p.nb_dual_cells + p.nb_clipped_cells > 0) {
               std::fprintf(stderr,
                            "  [cells %.2fs (%d dual, %d clipped), Delaunay %.2fs (%s%d flips",
                            p.seconds_cells, p.nb_dual_cells, p.nb_clipped_cells,
                            p.seconds_delaunay, p.rebuilt ? "rebuilt, " : "", p.nb_flips);
               if (p.nb_stuck_faces + p.nb_short_moves > 0)
                 std::fprintf(stderr, ", %d faces not Delaunay, %d moves short", p.nb_stuck_faces,
                              p.nb_short_moves);
               std::fprintf(stderr, "), %.2fs]", p.seconds_other);
             }
             std::fprintf(stderr, "\n");
           };
         const OptimizeResult r = optimize(d, *opt);
         cad.reset();  // the writer starts from a clean Gmsh
         opt->boundary_model = nullptr;
         write_mesh(d, out->path, out->to_write_options(d, in->path));
         QualityTable t;
         QualityStats before = r.before, after = r.after;
         before.label = "input";
         after.label = r.method;
         after.extra.push_back({"iterations", static_cast<double>(r.iterations)});
         after.extra.push_back({"seconds", r.seconds});
         t.columns = {before, after};
         if (!*quiet) std::cerr << t.to_text();
         if (!*quiet && r.boundary_free)
           std::fprintf(stderr,
                        "free boundary: %s geometry, %d surface, %d curve, %d fixed vertices; "
                        "%d vertices moved, Hausdorff %.3e (%.2e of the diagonal, "
                        "bound %.3e), volume change %.4f %%, worst boundary triangle Q %.4f -> "
                        "%.4f\n",
                        r.boundary_geometry.c_str(), r.nb_surface_vertices, r.nb_curve_vertices,
                        r.nb_fixed_vertices, r.nb_boundary_moved, r.hausdorff,
                        r.hausdorff / r.diagonal, r.hausdorff_tolerance, 100 * r.volume_change,
                        r.tri_q_min_before, r.tri_q_min_after);
         for (const auto& note : r.notes) std::cerr << "cvtmesh: note: " << note << "\n";
         const bool capped = !r.converged && !r.kept_input;
         if (capped)
           std::cerr << "cvtmesh: warning: '" << r.method << "' stopped at the iteration cap ("
                     << r.iterations << " iterations) before converging; raise --max-iterations "
                     << "or --tolerance\n";
         std::cerr << "cvtmesh: wrote " << out->path << " (" << r.method << ", " << r.iterations
                   << " iterations, " << (r.converged ? "converged" : "not converged")
                   << (r.kept_input ? ", input kept unchanged" : "") << ")\n";
         const bool fell_back = r.kept_input || r.method != opt->method;
         return *strict && (capped || fell_back) ? 6 : 0;
       }});
}

}  // namespace cvtmesh::cli
