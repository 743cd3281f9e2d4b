// cvtmesh stats IN: the quality table of one mesh.
#include <iostream>
#include <memory>

#include "convert/cli_common.h"

namespace cvtmesh::cli {

void register_stats(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  auto format = std::make_shared<std::string>("text");
  auto label = std::make_shared<std::string>();
  auto fe = std::make_shared<FeOptions>();
  CLI::App* c = app.add_subcommand(
      "stats", "print the quality table (the paper's Table 6/7 rows in 3D, Tables 1-5 in 2D)");
  add_input(c, *in);
  c->add_option("--format", *format, "text, markdown or json")
      ->check(CLI::IsMember({"text", "markdown", "json"}));
  c->add_option("--label", *label, "column label (default: the file name)");
  add_fe_options(c, *fe);
  commands().push_back({c, [in, format, label, fe] {
                          const MeshData d = read_mesh(in->path, in->to_read_options());
                          QualityTable t;
                          const std::string l = label->empty() ? in->path : *label;
                          t.columns.push_back(d.dim == 3 ? quality_stats(d.tet, l)
                                                         : quality_stats(d.tri, l));
                          add_fe_measures(t.columns.back(), d, *fe);
                          std::cout << render(t, *format);
                          return 0;
                        }});
}

}  // namespace cvtmesh::cli
