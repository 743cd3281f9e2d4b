#include "plugin/gmsh_gui.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>
#include <system_error>

#include "core/io/camera_cut.h"
#include "core/io/geo_scan.h"
#include "core/io/gmsh_session.h"
#include "core/io/gmsh_surface_mesh3.h"
#include "core/io/process_guard.h"
#include "core/io/read_mesh.h"
#include "core/util/error.h"

namespace cvtmesh {
namespace {

nlohmann::ordered_json to_json(const OnelabParam& p) {
  nlohmann::ordered_json j;
  j["type"] = p.is_string ? "string" : "number";
  j["name"] = p.name;
  if (!p.help.empty()) j["help"] = p.help;
  if (p.never_changed) j["changedValue"] = 0;
  j["visible"] = p.visible;
  j["readOnly"] = p.read_only;
  if (!p.attributes.empty()) {
    nlohmann::ordered_json a = nlohmann::ordered_json::object();
    for (const auto& [k, v] : p.attributes) a[k] = v;
    j["attributes"] = a;
  }
  if (p.is_string) {
    j["values"] = {p.text};
    if (!p.labels.empty()) j["choices"] = p.labels;
  } else {
    j["values"] = {p.number};
    if (p.max > p.min) {
      j["min"] = p.min;
      j["max"] = p.max;
      j["step"] = p.step;
    }
    if (!p.choices.empty()) j["choices"] = p.choices;
    if (!p.labels.empty()) {
      nlohmann::ordered_json l = nlohmann::ordered_json::object();
      for (std::size_t i = 0; i < p.labels.size() && i < p.choices.size(); ++i)
        l[p.labels[i]] = p.choices[i];
      j["valueLabels"] = l;
    }
  }
  return j;
}

}  // namespace

std::string onelab_json(const std::vector<OnelabParam>& params) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& p : params) j.push_back(to_json(p));
  return j.dump();
}

void LocalOnelab::set(const OnelabParam& p) {
  gmsh_checked("cannot set ONELAB parameter '" + p.name + "'",
               [&] { gmsh::onelab::set(onelab_json({p}), "json"); });
}

std::optional<double> LocalOnelab::number(const std::string& name) {
  std::vector<double> v;
  gmsh::onelab::getNumber(name, v);
  if (v.empty()) return std::nullopt;
  return v[0];
}

std::optional<std::string> LocalOnelab::string(const std::string& name) {
  std::vector<std::string> v;
  gmsh::onelab::getString(name, v);
  if (v.empty()) return std::nullopt;
  return v[0];
}

void LocalOnelab::info(const std::string& message) {
  gmsh::logger::write(message, "info");
}

void LocalOnelab::error(const std::string& message) {
  // With General.AbortOnError = 2 (the SDK's default) Gmsh throws the message back at us when no
  // GUI is running: a report must not become an exception.
  double abort = 0;
  gmsh::option::getNumber("General.AbortOnError", abort);
  gmsh::option::setNumber("General.AbortOnError", 0);
  try {
    gmsh::logger::write(message, "error");
  } catch (...) {
  }
  gmsh::option::setNumber("General.AbortOnError", abort);
}

void LocalOnelab::progress(const std::string& message) {
  if (gmsh::fltk::isAvailable())
    gmsh::fltk::setStatusMessage(message, false);
  else
    gmsh::logger::write(message, "info");
}

void gui_initialize(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  gmsh_checked("cannot start Gmsh",
               [&] { gmsh::initialize(static_cast<int>(args.size()), argv.data(), true); });
  set_gmsh_initialized_by_caller(true);  // our sessions use this Gmsh, never re-initialize it
}

void gui_finalize() {
  gmsh::finalize();
}

void gui_open(const std::string& path, bool allow_system_calls) {
  // Gmsh would silently start a new, empty model for a missing file.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError("cannot open '" + path + "': no such file");
  // A script that would start programs is refused as by the CLI (core/io/geo_scan.h).
  if (!allow_system_calls && gmsh_parses_as_script(file_extension(path))) {
    const auto findings = scan_geo_for_processes(path);
    if (!findings.empty()) throw InputError(geo_scan_message(findings));
  }
  gmsh_checked("cannot open '" + path + "'", [&] {
    std::optional<ProcessGuard> guard;
    if (!allow_system_calls) guard.emplace();
    gmsh::open(path);
    if (guard && !guard->refused().empty())
      throw InputError("'" + path + "': Gmsh was asked to run '" + guard->refused().front() +
                       "'; refused (cvtmesh-gui --allow-system-calls allows it)");
  });
}

int gui_model_dim() {
  const int d = gmsh::model::getDimension();
  if (d != 2) return d;
  // Surfaces in space that bound no volume: a surface mesh in space, optimized as a 3D mesh
  // (core/io/gmsh_surface_mesh3.h); meshed, its nodes say so, else the model's extent in z.
  std::vector<int> types;
  gmsh::model::mesh::getElementTypes(types, 2, -1);
  if (!types.empty()) {
    GmshSession session;
    return gmsh_surface_mesh_in_space() ? 3 : 2;
  }
  double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  const double size = std::max({x1 - x0, y1 - y0, z1 - z0});
  return z1 - z0 > 1e-10 * size ? 3 : 2;
}

void gui_set_button(const std::string& label, const std::string& action) {
  // Two values, [label, action], always (ONELAB updates values index by index).
  nlohmann::ordered_json b;
  b["type"] = "string";
  b["name"] = "ONELAB/Button";
  b["values"] = {label, action};
  b["visible"] = false;
  gmsh::onelab::set(nlohmann::ordered_json::array({b}).dump(), "json");
  // ONELAB/Action is created invisible, or the first press shows it as a field in the tree.
  std::vector<std::string> cur;
  gmsh::onelab::getString("ONELAB/Action", cur);
  if (cur.empty()) {
    OnelabParam a;
    a.name = "ONELAB/Action";
    a.is_string = true;
    a.visible = false;
    gmsh::onelab::set(onelab_json({a}), "json");
  }
}

std::string gui_take_action() {
  std::vector<std::string> v;
  gmsh::onelab::getString("ONELAB/Action", v);
  if (v.empty() || v[0].empty()) return "";
  gmsh::onelab::setString("ONELAB/Action", {""});
  return v[0];
}

void gui_post_action(const std::string& action) {
  gmsh::onelab::setString("ONELAB/Action", {action});
  if (gmsh::fltk::isAvailable()) gmsh::fltk::awake("update");
}

void gui_start(int min_menu_width) {
  gmsh_checked("cannot open the Gmsh window (is DISPLAY set?)", [&] {
    double w = 0;
    gmsh::option::getNumber("General.MenuWidth", w);
    if (w < min_menu_width) gmsh::option::setNumber("General.MenuWidth", min_menu_width);
    gmsh::fltk::initialize();
    if (!gmsh::fltk::isAvailable()) throw InputError("no graphical user interface available");
  });
}

bool gui_wait(double seconds) {
  if (!gmsh::fltk::isAvailable()) return false;
  gmsh::fltk::wait(seconds);
  return gmsh::fltk::isAvailable() != 0;
}

void gui_awake() {
  gmsh::fltk::awake("update");
}

GuiLock::GuiLock() {
  gmsh::fltk::lock();
}
GuiLock::~GuiLock() {
  gmsh::fltk::unlock();
}

void gui_refresh() {
  if (!gmsh::fltk::isAvailable()) return;
  // Gmsh caches the vertex arrays of the mesh display: changing a mesh display option rebuilds
  // them (GMSH-NOTES: the view does not redraw after the nodes moved).
  double n = 1;
  gmsh::option::getNumber("Mesh.NumSubEdges", n);
  gmsh::option::setNumber("Mesh.NumSubEdges", n + 1);
  gmsh::option::setNumber("Mesh.NumSubEdges", n);
  gmsh::fltk::update();
  gmsh::graphics::draw();
}

namespace {

std::string view_option(int tag, const std::string& name) {
  return "View[" + std::to_string(gmsh::view::getIndex(tag)) + "]." + name;
}

}  // namespace

void gui_show_view(int tag, double vmin, double vmax, bool cut) {
  cut = cut && gmsh::model::getDimension() == 3;  // a planar mesh is seen whole
  std::vector<int> tags;
  gmsh::view::getTags(tags);
  for (int t : tags) {
    double type = 1;
    gmsh::option::getNumber(view_option(t, "Type"), type);
    if (t != tag && type == 1) gmsh::option::setNumber(view_option(t, "Visible"), 0);
  }
  const std::string v = "View[" + std::to_string(gmsh::view::getIndex(tag)) + "].";
  gmsh::option::setNumber(v + "Visible", 1);
  if (vmax <= vmin) {  // the range of the values
    gmsh::option::getNumber(v + "Min", vmin);
    gmsh::option::getNumber(v + "Max", vmax);
  }
  if (vmax > vmin) {
    gmsh::option::setNumber(v + "RangeType", 2);  // custom: unchanged by the cut
    gmsh::option::setNumber(v + "CustomMin", vmin);
    gmsh::option::setNumber(v + "CustomMax", vmax);
  }
  gmsh::option::setNumber(v + "Clip", cut ? 1 : 0);
  if (cut) {
    double x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
    gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
    double r[3] = {0, 0, 0};
    gmsh::option::getNumber("General.RotationX", r[0]);
    gmsh::option::getNumber("General.RotationY", r[1]);
    gmsh::option::getNumber("General.RotationZ", r[2]);
    const auto plane = camera_cut_plane(camera_direction(r[0], r[1], r[2]),
                                        {0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1)});
    gmsh::option::setNumber("General.Clip0A", plane[0]);
    gmsh::option::setNumber("General.Clip0B", plane[1]);
    gmsh::option::setNumber("General.Clip0C", plane[2]);
    gmsh::option::setNumber("General.Clip0D", plane[3]);
    gmsh::option::setNumber("General.ClipWholeElements", 1);
    gmsh::option::setNumber("Mesh.Clip", 1);
  }
  if (gmsh::fltk::isAvailable()) {
    gmsh::fltk::update();
    gmsh::graphics::draw();
  }
}

namespace {

// The histogram graph sits at the top left of the graphics window, over the model when the camera
// fits it to the whole window. If the camera is still Gmsh's fit (scale 1, no translation), the
// model is drawn at 0.68 of that size, moved down by 0.12 and right by 0.04 of its bounding box's
// diagonal (screen units of the model): in the GUI test's window (520 x 630 pixels of graphics)
// and 3/4 view of the cube-minus-ball the model is then whole and below the graph. A camera the
// user has moved is left alone.
void make_room_for_graph() {
  double sx = 1, tx = 0, ty = 0;
  gmsh::option::getNumber("General.ScaleX", sx);
  gmsh::option::getNumber("General.TranslationX", tx);
  gmsh::option::getNumber("General.TranslationY", ty);
  if (sx != 1 || tx != 0 || ty != 0) return;
  double xmin, ymin, zmin, xmax, ymax, zmax;
  gmsh::model::getBoundingBox(-1, -1, xmin, ymin, zmin, xmax, ymax, zmax);
  const double dx = xmax - xmin, dy = ymax - ymin, dz = zmax - zmin;
  const double diagonal = std::sqrt(dx * dx + dy * dy + dz * dz);
  if (!(diagonal > 0) || !std::isfinite(diagonal)) return;
  for (const char* k : {"General.ScaleX", "General.ScaleY", "General.ScaleZ"})
    gmsh::option::setNumber(k, 0.68);
  gmsh::option::setNumber("General.TranslationX", 0.04 * diagonal);
  gmsh::option::setNumber("General.TranslationY", -0.12 * diagonal);
}

}  // namespace

int gui_add_histogram_view(const std::vector<QualityHistogram>& series, const std::string& name) {
  const int tag = gmsh::view::add(name);
  // Scalar points along the x axis, two per bin (its left and right edge, the same value): the
  // curvilinear abscissa of a "2D space" graph is then Q itself and the curve is a step.
  const std::size_t bins = series.empty() ? 0 : series.front().fraction.size();
  std::vector<double> data;
  int nb_points = 0;
  double top = 0;
  for (std::size_t b = 0; b < bins; ++b)
    for (int side = 0; side < 2; ++side) {
      data.insert(data.end(), {static_cast<double>(b + side) / bins, 0, 0});
      for (const auto& h : series) {
        const double pct = b < h.fraction.size() ? 100 * h.fraction[b] : 0;
        data.push_back(pct);
        top = std::max(top, pct);
      }
      ++nb_points;
    }
  gmsh::view::addListData(tag, "SP", nb_points, data);
  const std::string v = "View[" + std::to_string(gmsh::view::getIndex(tag)) + "].";
  gmsh::option::setNumber(v + "Type", 2);  // 2D space: value against the abscissa along the points
  gmsh::option::setNumber(v + "Axes", 2);  // box with ticks
  gmsh::option::setString(v + "AxesLabelX", "Q");
  gmsh::option::setString(v + "AxesFormatX", "%.1f");
  gmsh::option::setString(v + "AxesFormatY", "%.0f");
  gmsh::option::setNumber(v + "ShowTime", 0);
  gmsh::option::setNumber(v + "RangeType", 2);
  gmsh::option::setNumber(v + "CustomMin", 0);
  gmsh::option::setNumber(v + "CustomMax", top > 0 ? top : 1);
  gmsh::option::setNumber(v + "LineWidth", 2);
  // Top left of the graphics window, about a quarter of its width (make_room_for_graph).
  double w = 600, h = 600;
  gmsh::option::getNumber("General.GraphicsWidth", w);
  gmsh::option::getNumber("General.GraphicsHeight", h);
  gmsh::option::setNumber(v + "AutoPosition", 0);
  gmsh::option::setNumber(v + "PositionX", 60);
  gmsh::option::setNumber(v + "PositionY", 40);
  gmsh::option::setNumber(v + "Width", std::max(200.0, 0.26 * w));
  gmsh::option::setNumber(v + "Height", std::max(120.0, 0.22 * h));
  make_room_for_graph();
  return tag;
}

int gui_mark_views_stale(const std::vector<std::string>& names) {
  int n = 0;
  std::vector<int> tags;
  gmsh::view::getTags(tags);
  for (int t : tags) {
    std::string name;
    gmsh::option::getString(view_option(t, "Name"), name);
    if (std::find(names.begin(), names.end(), name) == names.end()) continue;
    gmsh::option::setString(view_option(t, "Name"), name + " (stale)");
    ++n;
  }
  if (n > 0 && gmsh::fltk::isAvailable()) {
    gmsh::fltk::update();
    gmsh::graphics::draw();
  }
  return n;
}

std::string gui_display_json() {
  auto num = [](const std::string& name) {
    double v = 0;
    gmsh::option::getNumber(name, v);
    return v;
  };
  nlohmann::ordered_json j;
  j["views"] = nlohmann::ordered_json::array();
  std::vector<int> tags;
  gmsh::view::getTags(tags);
  for (int t : tags) {
    std::string name;
    gmsh::option::getString(view_option(t, "Name"), name);
    nlohmann::ordered_json v;
    v["tag"] = t;
    v["name"] = name;
    v["type"] = static_cast<int>(num(view_option(t, "Type")));
    v["visible"] = static_cast<int>(num(view_option(t, "Visible")));
    v["range_type"] = static_cast<int>(num(view_option(t, "RangeType")));
    v["custom_min"] = num(view_option(t, "CustomMin"));
    v["custom_max"] = num(view_option(t, "CustomMax"));
    v["min"] = num(view_option(t, "Min"));
    v["max"] = num(view_option(t, "Max"));
    v["clip"] = static_cast<int>(num(view_option(t, "Clip")));
    j["views"].push_back(v);
  }
  j["clip_plane"] = {num("General.Clip0A"), num("General.Clip0B"), num("General.Clip0C"),
                     num("General.Clip0D")};
  j["mesh_clip"] = static_cast<int>(num("Mesh.Clip"));
  const auto n = camera_direction(num("General.RotationX"), num("General.RotationY"),
                                  num("General.RotationZ"));
  j["toward_camera"] = {n[0], n[1], n[2]};
  return j.dump();
}

std::string gui_mesh_signature() {
  std::vector<std::size_t> tags;
  std::vector<double> xyz, uvw;
  gmsh::model::mesh::getNodes(tags, xyz, uvw, -1, -1, false, false);
  // FNV-1a over the tags and the coordinates' bytes.
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](const void* p, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  };
  mix(tags.data(), tags.size() * sizeof(std::size_t));
  mix(xyz.data(), xyz.size() * sizeof(double));
  return std::to_string(tags.size()) + ":" + std::to_string(h);
}

}  // namespace cvtmesh
