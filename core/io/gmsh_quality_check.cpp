#include "core/io/gmsh_quality_check.h"

#include <gmsh.h>

#include <algorithm>
#include <string>
#include <unordered_map>

#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/util/error.h"

namespace cvtmesh {

std::vector<double> gmsh_icn_per_element(const MeshData& data) {
  GmshSession session;
  std::string previous;
  gmsh::model::getCurrent(previous);
  std::vector<int> before;
  gmsh::view::getTags(before);
  std::vector<int> made;
  std::vector<double> out;
  auto cleanup = [&] {
    for (int v : made) gmsh::view::remove(v);
    gmsh::model::remove();
    if (!previous.empty() && !session.owns()) gmsh::model::setCurrent(previous);
  };
  const GmshWritten written = mesh_to_gmsh(data, "cvtmesh_icn_check");
  try {
    gmsh_checked("Gmsh's AnalyseMeshQuality plugin failed", [&] {
      const std::string plugin = "AnalyseMeshQuality";
      gmsh::plugin::setNumber(plugin, "JacobianDeterminant", 0);
      gmsh::plugin::setNumber(plugin, "IGEMeasure", 0);
      gmsh::plugin::setNumber(plugin, "ICNMeasure", 1);
      gmsh::plugin::setNumber(plugin, "Recompute", 1);
      gmsh::plugin::setNumber(plugin, "CreateView", 1);
      gmsh::plugin::setNumber(plugin, "DimensionOfElements", data.dim);
      gmsh::plugin::run(plugin);
      std::vector<int> after;
      gmsh::view::getTags(after);
      for (int v : after)
        if (std::find(before.begin(), before.end(), v) == before.end()) made.push_back(v);
      const std::string want = "ICN " + std::to_string(data.dim) + "D";
      int view = -1;
      for (int v : made) {
        std::string name;
        gmsh::option::getString("View[" + std::to_string(gmsh::view::getIndex(v)) + "].Name", name);
        if (name == want) view = v;
      }
      if (view < 0) throw InputError("the plugin made no '" + want + "' view");
      std::string type;
      std::vector<std::size_t> tags;
      std::vector<std::vector<double>> values;
      double time = 0;
      int ncomp = 0;
      gmsh::view::getModelData(view, 0, type, tags, values, time, ncomp);
      std::unordered_map<std::size_t, double> by_tag;
      by_tag.reserve(tags.size() * 2);
      for (std::size_t i = 0; i < tags.size() && i < values.size(); ++i)
        if (!values[i].empty()) by_tag[tags[i]] = values[i][0];
      out.reserve(written.element_tags.size());
      for (std::size_t tag : written.element_tags) {
        auto it = by_tag.find(tag);
        if (it == by_tag.end())
          throw InputError("the plugin reported no ICN for element " + std::to_string(tag));
        out.push_back(it->second);
      }
    });
  } catch (...) {
    cleanup();
    throw;
  }
  cleanup();
  return out;
}

}  // namespace cvtmesh
