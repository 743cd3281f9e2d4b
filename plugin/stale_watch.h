// Marks the views of a run stale: after a run (or Show quality) the GUI arms the watch with the
// options it ran with; while armed, check() compares the model's mesh (gui_mesh_signature) and
// the panel's options (panel_signature) with those, and at the first difference renames the
// quality views and the histogram "<name> (stale)" (gui_mark_views_stale) and disarms. The next
// run removes the stale views with the others.
#pragma once
#include <string>

namespace cvtmesh::plugin {

class StaleWatch {
 public:
  // Remembers the current mesh and `options_signature` (panel_signature of the run's options).
  void arm(const std::string& options_signature);
  void disarm() { armed_ = false; }
  bool armed() const { return armed_; }
  // "" while nothing changed (or not armed); else what changed ("mesh" or "options"), after the
  // views were marked and the watch disarmed.
  std::string check(const std::string& options_signature);

 private:
  bool armed_ = false;
  std::string mesh_, options_;
};

}  // namespace cvtmesh::plugin
