// ONELAB and FLTK helpers for the Gmsh front ends (plugin/): a parameter description the panel is
// written in, the interface of a ONELAB parameter tree, the tree of the Gmsh GUI running in this
// process (gmsh::onelab) and the calls that drive that GUI (gmsh::fltk). Every Gmsh SDK call of
// the front ends is here or in gmsh_inprocess.h. (The tree of a *stock* Gmsh that launched us as
// a ONELAB client is reached over its socket with the header-only client of gmsh-doc, not with the
// SDK: see plugin/onelab_remote.h.)
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/quality/quality_histogram.h"

namespace cvtmesh {

// One ONELAB parameter. The name is the path in the tree ("Group/Sub/0Label": '/' separates
// levels; leading digits order the entries and are not displayed).
struct OnelabParam {
  std::string name;
  bool is_string = false;
  double number = 0;
  std::string text;
  // Numbers: allowed values, with one label each in `labels` (a drop-down), or {0, 1} without
  // labels (a check box). Strings: `labels` are the choices.
  std::vector<double> choices;
  std::vector<std::string> labels;
  double min = 0, max = 0, step = 0;  // numbers: range and step when max > min
  bool read_only = false;
  bool visible = true;
  bool never_changed = false;  // setting it does not mark the model as changed (results)
  std::string help;
  std::vector<std::pair<std::string, std::string>> attributes;  // e.g. {"Highlight", "AliceBlue"}
};

// The parameter tree a front end talks to, and the places its messages go.
class OnelabTree {
 public:
  virtual ~OnelabTree() = default;
  // Creates the parameter or overwrites it (value and attributes).
  virtual void set(const OnelabParam& p) = 0;
  // The current value, if the parameter exists.
  virtual std::optional<double> number(const std::string& name) = 0;
  virtual std::optional<std::string> string(const std::string& name) = 0;
  // Gmsh's message console (info, error) and status bar (progress).
  virtual void info(const std::string& message) = 0;
  virtual void error(const std::string& message) = 0;
  virtual void progress(const std::string& message) = 0;
};

// The ONELAB database of the Gmsh of this process (the GUI opened by gui_start, or none).
class LocalOnelab : public OnelabTree {
 public:
  void set(const OnelabParam& p) override;
  std::optional<double> number(const std::string& name) override;
  std::optional<std::string> string(const std::string& name) override;
  void info(const std::string& message) override;
  void error(const std::string& message) override;
  void progress(const std::string& message) override;
};

// Gmsh's JSON for a list of parameters (what gmsh::onelab::set takes).
std::string onelab_json(const std::vector<OnelabParam>& params);

// ---- The Gmsh GUI in this process (cvtmesh-gui) ----------------------------------------------

// gmsh::initialize with a command line (args[0] is the program name; Gmsh options such as
// -setnumber may follow). Throws InputError if Gmsh rejects it.
void gui_initialize(const std::vector<std::string>& args);
void gui_finalize();
// Opens a model or mesh file as the current model (gmsh::open). Throws InputError (also for a
// missing file, which Gmsh itself would silently take as a new model).
// A script that would start a program (SystemCall, OnelabRun, ... in it or what it includes) is
// refused with InputError naming the file, line and command unless allow_system_calls.
void gui_open(const std::string& path, bool allow_system_calls = false);
// The dimension of the mesh the panel optimizes: the current model's highest entity dimension,
// -1 if empty, but 3 for surfaces in space that bound no volume (a surface mesh in space).
int gui_model_dim();
// Sets the big Run button of the ONELAB panel: pressing it sets ONELAB/Action to `action`.
void gui_set_button(const std::string& label, const std::string& action);
// The pending ONELAB action ("" if none), reset to "" so that it is handled once.
std::string gui_take_action();
// Posts an action as if a button had been pressed (wakes the event loop up).
void gui_post_action(const std::string& action);
// Opens the window, the menu tree at least min_menu_width pixels wide (ONELAB labels are clipped
// otherwise). Throws InputError if there is no display.
void gui_start(int min_menu_width = 0);
// Processes events for at most `seconds` (< 0: until one arrives). False once the window is closed.
bool gui_wait(double seconds = -1);
// From another thread: ask the event loop to wake up; lock around GUI calls from that thread.
void gui_awake();
class GuiLock {
 public:
  GuiLock();
  ~GuiLock();
  GuiLock(const GuiLock&) = delete;
  GuiLock& operator=(const GuiLock&) = delete;
};
// Redraws the model after its mesh was replaced (Gmsh does not notice node moves by itself) and
// refreshes the ONELAB tree.
void gui_refresh();
// Shows the view `tag` alone (the other views hidden, graphs excepted), coloured per element over
// [vmin, vmax] (vmax <= vmin: the range of its values, set as a custom range so that it stays
// when the cut hides some elements). With cut, a 3D model is clipped by the plane through the
// centre of its bounding box that faces the camera (core/io/camera_cut.h), whole elements kept,
// the half nearer to the camera removed, so that the quality inside shows and not only on the
// boundary (Tools > Clipping turns it off).
void gui_show_view(int tag, double vmin = 0, double vmax = 0, bool cut = false);

// Adds a view named `name` that Gmsh draws as a 2D graph (View.Type 2, "2D space"): the
// histograms as step curves over Q in [0, 1], in % of elements (the curve coloured by its value),
// one time step per series (all with the same number of bins). Returns its tag.
int gui_add_histogram_view(const std::vector<QualityHistogram>& series, const std::string& name);

// Renames every view named as one of `names` to "<name> (stale)" (a view already marked is left
// alone); returns how many were renamed.
int gui_mark_views_stale(const std::vector<std::string>& names);

// What the window shows, read back through Gmsh's option API (for --result-json and the tests):
// {"views": [{"tag", "name", "type" (1: 3D, 2: 2D space graph, ...), "visible", "range_type",
// "custom_min", "custom_max", "min", "max", "clip"}...], "clip_plane": [A, B, C, D], "mesh_clip",
// "toward_camera": the camera direction of General.RotationX/Y/Z (core/io/camera_cut.h)}.
std::string gui_display_json();

// A fingerprint of the current model's mesh (node count, element count, a hash of the node
// coordinates): it changes when the mesh is regenerated, edited or replaced.
std::string gui_mesh_signature();

}  // namespace cvtmesh
