#include "convert/schema_cli.h"

#include <algorithm>
#include <type_traits>

#include "core/pipeline/method_registry.h"
#include "core/pipeline/option_schema.h"
#include "core/pipeline/optimize.h"

namespace cvtmesh::cli {

// One CLI flag per option of the schema (core/pipeline/option_schema.h): its flag, help, default
// and range come from there, and optimize() validates the values (OptionError, exit 2), so the
// CLI refuses a bad value with the same message as Python and the GUI panel.
void add_schema_options(CLI::App* c, OptimizeOptions& o, const std::vector<std::string>& except) {
  for (const OptionSpec& s : option_schema()) {
    if (!(s.fronts & kCli) || s.flag.empty()) continue;
    if (std::find(except.begin(), except.end(), s.name) != except.end()) continue;
    std::string help = describe(s);
    if (s.name == "method") help += "\n" + methods_help();
    std::visit(
        [&](auto f) {
          using T = std::decay_t<decltype(o.*f)>;
          if constexpr (std::is_same_v<T, bool>) {
            // "--no-x" turns a default-on switch off (a callback: CLI11 prints no "{false}").
            bool* field = &(o.*f);
            const bool value = s.flag.rfind("--no-", 0) != 0;
            c->add_flag_callback(
                s.flag, [field, value] { *field = value; }, help);
          } else {
            c->add_option(s.flag + (s.name == "method" ? ",-m" : ""), o.*f, help);
          }
        },
        s.field);
  }
}

}  // namespace cvtmesh::cli
