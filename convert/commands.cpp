#include "convert/commands.h"

#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "core/io/read_mesh.h"
#include "core/io/write_mesh.h"
#include "core/quality/quality_table.h"

namespace cvtmesh::cli {
namespace {

struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;
};
std::vector<Command>& commands() {
  static std::vector<Command> c;
  return c;
}

// Options shared by the subcommands that read a mesh.
struct InputOpts {
  std::string path;
  int dim = -1;
  std::vector<std::string> set_numbers;
  double size_factor = 0;
  ReadOptions to_read_options() const {
    ReadOptions r;
    r.dim = dim;
    r.mesh_size_factor = size_factor;
    for (const auto& s : set_numbers) {
      const auto eq = s.find('=');
      if (eq == std::string::npos) throw CLI::ValidationError("--set", "expected NAME=VALUE, got '" + s + "'");
      r.set_numbers.push_back({s.substr(0, eq), std::stod(s.substr(eq + 1))});
    }
    return r;
  }
};

void add_input(CLI::App* c, InputOpts& in) {
  c->add_option("input", in.path, "input mesh or model (.msh, .geo, .stl, .mesh, .node, ...)")->required();
  c->add_option("--dim", in.dim, "read as a 2D (triangles) or 3D (tetrahedra) mesh; default: highest present")
      ->check(CLI::IsMember({-1, 2, 3}));
  c->add_option("--set", in.set_numbers, "NAME=VALUE: set a .geo parameter before meshing (like gmsh -setnumber)");
  c->add_option("--size-factor", in.size_factor, "Gmsh Mesh.MeshSizeFactor when a model is meshed");
}

struct OutputOpts {
  std::string path;
  bool quality = false;
  double msh_version = 4.1;
  bool binary = false;
  bool no_clobber = false;
  bool in_place = false;
  WriteOptions to_write_options(const MeshData& d, const std::string& input) const {
    WriteOptions w;
    w.msh_version = msh_version;
    w.binary = binary;
    if (quality) w.fields = quality_fields(d);
    w.policy.force = !no_clobber;
    w.policy.in_place = in_place;
    w.policy.input_path = input;
    return w;
  }
};

void add_output_flags(CLI::App* c, OutputOpts& o) {
  c->add_flag("--quality", o.quality, "store per-element quality (Q, radius ratio, min angle) as element data");
  c->add_option("--msh-version", o.msh_version, "version of a .msh output: 4.1 (default) or 2.2")
      ->check(CLI::IsMember({4.1, 2.2}));
  c->add_flag("--binary", o.binary, "binary .msh output");
  c->add_flag("--no-clobber", o.no_clobber, "refuse to replace an existing output file (default: replace it, like gmsh -o)");
  c->add_flag("--in-place", o.in_place, "allow the output to be the input file itself");
}

std::string render(const QualityTable& t, const std::string& format) {
  if (format == "markdown") return t.to_markdown();
  if (format == "json") return t.to_json();
  return t.to_text();
}

void register_stats(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  auto format = std::make_shared<std::string>("text");
  auto label = std::make_shared<std::string>();
  CLI::App* c = app.add_subcommand("stats", "print the quality table (the paper's Table 6/7 rows in 3D, Tables 1-5 in 2D)");
  add_input(c, *in);
  c->add_option("--format", *format, "text, markdown or json")->check(CLI::IsMember({"text", "markdown", "json"}));
  c->add_option("--label", *label, "column label (default: the file name)");
  commands().push_back({c, [in, format, label] {
                          const MeshData d = read_mesh(in->path, in->to_read_options());
                          QualityTable t;
                          const std::string l = label->empty() ? in->path : *label;
                          t.columns.push_back(d.dim == 3 ? quality_stats(d.tet, l) : quality_stats(d.tri, l));
                          std::cout << render(t, *format);
                          return 0;
                        }});
}

void register_convert(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  auto out = std::make_shared<OutputOpts>();
  CLI::App* c = app.add_subcommand("convert", "convert a mesh between formats (by extension), optionally with quality data");
  add_input(c, *in);
  c->add_option("output", out->path, "output file; format by extension: " + supported_write_formats())->required();
  add_output_flags(c, *out);
  commands().push_back({c, [in, out] {
                          const MeshData d = read_mesh(in->path, in->to_read_options());
                          write_mesh(d, out->path, out->to_write_options(d, in->path));
                          std::cerr << "cvtmesh: wrote " << out->path << "\n";
                          return 0;
                        }});
}

}  // namespace

void register_commands(CLI::App& app) {
  register_stats(app);
  register_convert(app);
}

int run_selected(CLI::App& app) {
  for (const auto& c : commands())
    if (c.app->parsed()) return c.run();
  std::cerr << app.help();
  return 1;
}

}  // namespace cvtmesh::cli
