// cvtmesh perturb IN -o OUT --random|--cluster: the paper's RandPert / ClusPert initial meshes.
#include <iostream>
#include <memory>

#include "convert/cli_common.h"
#include "core/io/svg_io.h"
#include "core/pipeline/perturb2d.h"

namespace cvtmesh::cli {

void register_perturb(CLI::App& app) {
  struct Opts {
    InputOpts in;
    OutputOpts out;
    bool random = false, cluster = false;
    unsigned seed = 1;
    double amount = -1;
    std::string attractor = "auto";
    std::string svg;
  };
  auto o = std::make_shared<Opts>();
  CLI::App* c = app.add_subcommand("perturb",
                                   "perturb the interior vertices of a 2D mesh (the paper's "
                                   "RandPert / ClusPert) and re-triangulate it");
  add_input(c, o->in);
  c->add_option("-o,--output", o->out.path,
                "output mesh; format by extension: " + supported_write_formats())
      ->required();
  auto* r = c->add_flag("--random", o->random,
                        "RandPert: move each interior vertex randomly (uniform in a disk of radius "
                        "amount * local edge length)");
  auto* k = c->add_flag(
      "--cluster", o->cluster,
      "ClusPert: pull the interior vertices towards the attractor by the fraction amount");
  r->excludes(k);
  c->add_option("--seed", o->seed, "random seed (RandPert)");
  c->add_option("--amount", o->amount, "size of the perturbation (default 0.4 random, 0.5 cluster)")
      ->check(CLI::NonNegativeNumber);
  c->add_option("--attractor", o->attractor,
                "ClusPert attractor: auto (hole if any, else centre), centre, hole")
      ->check(CLI::IsMember({"auto", "centre", "center", "hole"}));
  c->add_option("--svg", o->svg,
                "also write an SVG picture of the perturbed mesh, coloured by quality");
  add_output_flags(c, o->out);
  commands().push_back({c, [o] {
                          if (o->random == o->cluster) {
                            std::cerr
                                << "cvtmesh perturb: give exactly one of --random or --cluster\n";
                            return kExitUsage;
                          }
                          ReadOptions ro = o->in.to_read_options();
                          if (ro.dim < 0) ro.dim = 2;
                          MeshData d = read_mesh(o->in.path, ro);
                          if (d.dim != 2) {
                            std::cerr << "cvtmesh perturb: '" << o->in.path
                                      << "' is not a 2D (triangle) mesh\n";
                            return 2;
                          }
                          Perturb2dOptions po;
                          po.kind = o->random ? Perturbation2d::kRandom : Perturbation2d::kCluster;
                          po.seed = o->seed;
                          po.amount = o->amount;
                          po.attractor = o->attractor;
                          const Perturb2dResult pr = perturb_2d(d.tri, po);
                          const WriteReport written =
                              write_mesh(d, o->out.path, o->out.to_write_options(d, o->in.path));
                          for (const auto& note : written.notes)
                            info() << "cvtmesh: note: " << note << "\n";
                          if (!o->svg.empty()) write_svg(d.tri, o->svg);
                          std::ostream& log = info();
                          log << "cvtmesh: perturbed " << pr.nb_moved << " vertices";
                          if (!pr.attractor.empty()) log << " towards the " << pr.attractor;
                          if (pr.nb_limited) log << " (" << pr.nb_limited << " moves shortened)";
                          log << "; wrote " << o->out.path << "\n";
                          return 0;
                        }});
}

}  // namespace cvtmesh::cli
