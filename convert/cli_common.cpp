#include "convert/cli_common.h"

#include <cstdlib>
#include <fstream>
#include <iostream>

#include "convert/json_report.h"
#include "core/io/atomic_file.h"
#include "core/io/read_msh_format.h"
#include "core/io/read_sizing_reference.h"
#include "core/pipeline/option_schema.h"
#include "core/util/error.h"
#include "core/quality/quality_fields.h"

namespace cvtmesh::cli {

std::vector<Command>& commands() {
  static std::vector<Command> c;
  return c;
}

GlobalOpts& global_opts() {
  static GlobalOpts g;
  return g;
}

void add_global_options(CLI::App& app) {
  GlobalOpts& g = global_opts();
  auto* q =
      app.add_flag("-q,--quiet", g.quiet, "nothing on stderr but errors (no progress, notes)");
  auto* v = app.add_flag("-v,--verbose", g.verbose,
                         "more detail on stderr (optimize: the timings of every iteration)");
  q->excludes(v);
  app.add_option("--threads", g.threads,
                 "threads of the parallel loops (default: OMP_NUM_THREADS, else every core)")
      ->check(CLI::PositiveNumber);
}

void apply_global_options() {
  // default_thread_count() reads OMP_NUM_THREADS on its first call, which comes later.
  if (global_opts().threads > 0)
    setenv("OMP_NUM_THREADS", std::to_string(global_opts().threads).c_str(), 1);
}

std::function<std::unique_ptr<PartExchange>()>& exchange_factory() {
  static std::function<std::unique_ptr<PartExchange>()> f = [] {
    return std::make_unique<SerialExchange>();
  };
  return f;
}

std::ostream& info() {
  static std::ostream sink(nullptr);  // no buffer: writes are dropped
  return global_opts().quiet ? sink : std::cerr;
}

ReadOptions InputOpts::to_read_options() const {
  ReadOptions r;
  r.dim = dim;
  r.mesh_size_factor = size_factor;
  r.allow_system_calls = allow_system_calls;
  for (const auto& s : set_numbers) {
    const auto eq = s.find('=');
    if (eq == std::string::npos)
      throw CLI::ValidationError("--set", "expected NAME=VALUE, got '" + s + "'");
    try {
      r.set_numbers.push_back({s.substr(0, eq), std::stod(s.substr(eq + 1))});
    } catch (const std::exception&) {
      throw CLI::ValidationError("--set", "expected a number in '" + s + "'");
    }
  }
  for (const auto& s : set_strings) {
    const auto eq = s.find('=');
    if (eq == std::string::npos)
      throw CLI::ValidationError("--set-string", "expected NAME=VALUE, got '" + s + "'");
    r.set_strings.push_back({s.substr(0, eq), s.substr(eq + 1)});
  }
  return r;
}

void load_sizing_reference(OptimizeOptions& o, const InputOpts& in) {
  if (!sizing_is_path(o)) return;
  ReadOptions ro;
  ro.allow_system_calls = in.allow_system_calls;
  o.sizing_reference = read_sizing_reference(o.sizing, in.dim, ro);
}

void add_input(CLI::App* c, InputOpts& in) {
  c->add_option("input", in.path, "input mesh or model (.msh, .geo, .stl, .mesh, .node, ...)")
      ->required();
  c->add_option("--dim", in.dim,
                "read as a 2D (triangles) or 3D (tetrahedra) mesh; default: highest present")
      ->check(CLI::IsMember({-1, 2, 3}));
  c->add_option("--set", in.set_numbers,
                "NAME=VALUE: set a .geo parameter before meshing (like gmsh -setnumber)");
  c->add_option("--set-string", in.set_strings,
                "NAME=VALUE: set a .geo string parameter (like gmsh -setstring)");
  c->add_option("--size-factor", in.size_factor, "Gmsh Mesh.MeshSizeFactor when a model is meshed");
  c->add_flag("--allow-system-calls", in.allow_system_calls,
              "let a .geo script (and what it includes) run programs (SystemCall, "
              "NonBlockingSystemCall, OnelabRun); refused by default");
}

WriteOptions OutputOpts::to_write_options(const MeshData& d, const std::string& input) const {
  WriteOptions w;
  // A .msh output takes the input's version and binary/ASCII mode unless told otherwise.
  const MshFormat f = read_msh_format(input);
  w.msh_version = msh_version > 0 ? msh_version : f.ok && f.version < 3 ? 2.2 : 4.1;
  w.binary = binary || (f.ok && f.binary && !ascii);
  if (quality) w.fields = quality_fields(d);
  w.policy.force = force || !no_clobber;
  w.save_all = save_all;
  w.policy.in_place = in_place;
  w.policy.input_path = input;
  return w;
}

void add_output_flags(CLI::App* c, OutputOpts& o) {
  c->add_flag("--quality", o.quality,
              "store per-element quality (Q, radius ratio, min angle) as element data");
  c->add_option("--msh-version", o.msh_version,
                "version of a .msh output: 4.1 or 2.2 (default: the input's if it is a .msh, "
                "else 4.1)")
      ->check(CLI::IsMember({4.1, 2.2}));
  c->add_flag("--binary", o.binary, "binary .msh output (default: as the input .msh)");
  c->add_flag("--ascii", o.ascii, "ASCII .msh output even if the input .msh is binary");
  c->add_flag("--no-clobber", o.no_clobber,
              "refuse to replace an existing output file (default: replace it, like gmsh -o)");
  c->add_flag("--force", o.force, "replace an existing output file even with --no-clobber");
  c->add_flag("--save-all", o.save_all,
              ".msh: write every element (like gmsh -save_all), not only those Gmsh would save "
              "(a model's physical groups, the blocks a .msh input held)");
  c->add_flag("--in-place", o.in_place, "allow the output to be the input file itself");
}

void write_text_file(const std::string& path, const std::string& text) {
  check_directory_writable(path);
  AtomicFile out(path);
  {
    std::ofstream f(out.temp_path(), std::ios::binary);
    f << text;
    if (!f.flush()) throw OutputError("cannot write '" + path + "'");
  }
  out.commit();
}

void add_fe_options(CLI::App* c, FeOptions& fe) {
  c->add_option("--fe-measures", fe.mode,
                "the FE measures (time step, element time step, CG iterations, stiffness "
                "condition): auto (meshes up to " +
                    std::to_string(kFeMeasuresAutoLimit) + " elements), on, off")
      ->check(CLI::IsMember({"auto", "on", "off"}));
  c->add_option("--wave-speed", fe.wave_speed,
                "wave speed c of the explicit time steps (they scale as 1/c; default 1)")
      ->check(CLI::PositiveNumber);
}

void add_fe_measures(QualityStats& s, const MeshData& d, const FeOptions& fe) {
  const FeMeasures m = d.dim == 3 ? fe_measures(d.tet, fe) : fe_measures(d.tri, fe);
  if (!m.measured && fe.mode == "auto")
    std::cerr << "cvtmesh: note: FE measures of '" << s.label << "' skipped: " << m.skipped << "\n";
  set_fe_measures(s, m);
}

std::string render(const QualityTable& t, const std::string& format) {
  if (format == "markdown") return t.to_markdown();
  if (format == "json") return table_json(t).dump(2) + "\n";
  return t.to_text();
}

}  // namespace cvtmesh::cli
