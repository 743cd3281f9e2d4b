// cvtmesh convert IN OUT: format conversion, optionally with per-element quality.
#include <iostream>
#include <memory>

#include "convert/cli_common.h"

namespace cvtmesh::cli {

void register_convert(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  auto out = std::make_shared<OutputOpts>();
  CLI::App* c = app.add_subcommand(
      "convert", "convert a mesh between formats (by extension), optionally with quality data");
  add_input(c, *in);
  c->add_option("output", out->path,
                "output file; format by extension: " + supported_write_formats())
      ->required();
  add_output_flags(c, *out);
  commands().push_back({c, [in, out] {
                          const MeshData d = read_mesh(in->path, in->to_read_options());
                          for (const auto& note : d.model().read_notes)
                            info() << "cvtmesh: note: " << note << "\n";
                          const WriteReport written =
                              write_mesh(d, out->path, out->to_write_options(d, in->path));
                          for (const auto& note : written.notes)
                            info() << "cvtmesh: note: " << note << "\n";
                          info() << "cvtmesh: wrote " << out->path << "\n";
                          return 0;
                        }});
}

}  // namespace cvtmesh::cli
