#include "plugin/stale_watch.h"

#include "plugin/gmsh_gui.h"
#include "plugin/gmsh_inprocess.h"

namespace cvtmesh::plugin {

void StaleWatch::arm(const std::string& options_signature) {
  mesh_ = gui_mesh_signature();
  options_ = options_signature;
  armed_ = true;
}

std::string StaleWatch::check(const std::string& options_signature) {
  if (!armed_) return "";
  std::string what;
  if (options_signature != options_)
    what = "options";
  else if (gui_mesh_signature() != mesh_)
    what = "mesh";
  if (what.empty()) return "";
  gui_mark_views_stale(our_view_names(false));
  armed_ = false;
  return what;
}

}  // namespace cvtmesh::plugin
