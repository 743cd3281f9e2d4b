// Shared pieces of the CLI subcommands: input/output option groups, the command registry.
#pragma once
#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "core/distributed/part_exchange.h"
#include "core/io/read_mesh.h"
#include "core/io/write_mesh.h"
#include "core/pipeline/optimize.h"
#include "core/quality/fe_measures.h"
#include "core/quality/quality_table.h"

namespace cvtmesh::cli {

// A registered subcommand: its CLI11 app and what runs when it is selected (returns exit code).
struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};
std::vector<Command>& commands();

// The exit codes of every subcommand (README, docs/cli.md).
inline constexpr int kExitOk = 0;
inline constexpr int kExitUsage = 1;        // bad command line (CLI11's parse errors map to it)
inline constexpr int kExitBadInput = 2;     // unreadable input, or a refused option value
inline constexpr int kExitCannotWrite = 3;  // the output cannot be written
inline constexpr int kExitInternal = 4;     // an invariant was violated (a bug): nothing written
inline constexpr int kExitCheckFailed = 5;  // `check` found problems
inline constexpr int kExitStrict = 6;       // `optimize --strict`: capped, fell back or kept input

// The options every subcommand takes (before or after its name): -q, -v, --threads.
struct GlobalOpts {
  bool quiet = false;    // nothing on stderr but errors
  bool verbose = false;  // more detail (optimize: internal timings per iteration)
  int threads = 0;       // OpenMP threads of the parallel loops (0: OMP_NUM_THREADS or all cores)
};
GlobalOpts& global_opts();
void add_global_options(CLI::App& app);
// Applies --threads (before anything reads the thread count).
void apply_global_options();
// The ranks of a partitioned optimization (`optimize --parts`): this process alone
// (SerialExchange: the parts in turn) unless the MPI front end (convert/mpi/) set its own.
std::function<std::unique_ptr<PartExchange>()>& exchange_factory();

// stderr, or a sink under -q: for progress, notes and "wrote ..." lines (not for errors).
std::ostream& info();

// Options of the subcommands that read a mesh.
struct InputOpts {
  std::string path;
  int dim = -1;
  std::vector<std::string> set_numbers;
  std::vector<std::string> set_strings;
  double size_factor = 0;
  bool allow_system_calls = false;
  ReadOptions to_read_options() const;
};
void add_input(CLI::App* c, InputOpts& in);

// --sizing FILE: reads the reference mesh into o.sizing_reference (a .geo is meshed by Gmsh);
// nothing for a sizing keyword. Call before the input is read (a .geo reference is a Gmsh model
// of its own). InputError naming the file (exit 2) if it cannot be read.
void load_sizing_reference(OptimizeOptions& o, const InputOpts& in);

// Options of the subcommands that write a mesh.
struct OutputOpts {
  std::string path;
  bool quality = false;
  double msh_version = 0;  // 0: the input's (.msh), else 4.1
  bool binary = false;
  bool ascii = false;
  bool no_clobber = false;
  bool force = false;  // overrides --no-clobber
  bool in_place = false;
  bool save_all = false;
  WriteOptions to_write_options(const MeshData& d, const std::string& input) const;
};
void add_output_flags(CLI::App* c, OutputOpts& o);

// The FE measures of the quality tables (stats, compare, bench; core/quality/fe_measures.h):
// --fe-measures auto|on|off and --wave-speed, declared here once.
void add_fe_options(CLI::App* c, FeOptions& fe);
// Sets s's FE measures of mesh d (a note on stderr when they are skipped for the size).
void add_fe_measures(QualityStats& s, const MeshData& d, const FeOptions& fe);

// Writes a text file (a JSON report) atomically; OutputError if it cannot.
void write_text_file(const std::string& path, const std::string& text);

// Renders a table as "text", "markdown" or "json" (json_report.h: {"schema", "meshes": [...]}).
std::string render(const QualityTable& t, const std::string& format);

// One register function per subcommand (convert/cmd_<name>.cpp).
void register_stats(CLI::App& app);
void register_convert(CLI::App& app);
void register_optimize(CLI::App& app);
void register_mesh(CLI::App& app);
void register_compare(CLI::App& app);
void register_check(CLI::App& app);
void register_bench(CLI::App& app);
void register_perturb(CLI::App& app);

}  // namespace cvtmesh::cli
