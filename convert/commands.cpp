#include "convert/commands.h"

#include <iostream>

#include "convert/cli_common.h"

namespace cvtmesh::cli {

void register_commands(CLI::App& app) {
  register_stats(app);
  register_convert(app);
  register_optimize(app);
  register_mesh(app);
  register_compare(app);
  register_check(app);
  register_bench(app);
  register_perturb(app);
}

int run_selected(CLI::App& app) {
  for (const auto& c : commands())
    if (c.app->parsed()) return c.run();
  std::cerr << app.help();
  return 1;
}

}  // namespace cvtmesh::cli
