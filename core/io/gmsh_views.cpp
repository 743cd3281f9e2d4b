#include "core/io/gmsh_views.h"

#include <gmsh.h>

#include <cmath>
#include <limits>
#include <unordered_map>

namespace cvtmesh {

std::vector<DataView> read_gmsh_views(const std::vector<int>& views, const MeshData& data,
                                      const std::string& what, std::vector<std::string>& notes) {
  std::vector<DataView> out;
  const bool three = data.dim == 3;
  const std::vector<std::size_t>& node_tags = three ? data.tet.node_tags : data.tri.node_tags;
  const std::vector<std::size_t>& cell_tags = three ? data.tet.tet_tags : data.tri.tri_tags;
  const std::vector<int>& cells = three ? data.tet.tets : data.tri.tris;
  const int npe = three ? 4 : 3;
  std::unordered_map<std::size_t, std::size_t> vertex_of, cell_of;  // tag -> index
  for (std::size_t v = 0; v < node_tags.size(); ++v) vertex_of.emplace(node_tags[v], v);
  std::size_t live = 0;
  for (std::size_t c = 0; c < cell_tags.size() && npe * c < cells.size(); ++c)
    if (cells[npe * c] >= 0) cell_of.emplace(cell_tags[c], live++);
  const std::size_t nv = node_tags.size();
  const std::uint64_t fingerprint = mesh_fingerprint(data);
  for (int tag : views) {
    const std::string index = std::to_string(gmsh::view::getIndex(tag));
    std::string name;
    gmsh::option::getString("View[" + index + "].Name", name);
    double nb_steps = 0;
    gmsh::option::getNumber("View[" + index + "].NbTimeStep", nb_steps);
    const std::string label = what + "'s view '" + name + "'";
    DataView v;
    v.name = name;
    v.fingerprint = fingerprint;
    bool kept = true;
    std::string why;
    std::size_t on_mesh = 0;
    for (int step = 0; step < static_cast<int>(nb_steps) && kept; ++step) {
      std::string type;
      std::vector<std::size_t> tags;
      std::vector<std::vector<double>> values;
      double time = 0;
      int components = 0;
      try {
        gmsh::view::getModelData(tag, step, type, tags, values, time, components);
      } catch (...) {
        kept = false;
        why = "it is not model-based (a list-based .pos view)";
        break;
      }
      if (type != "NodeData" && type != "ElementData") {
        kept = false;
        why = type + " is not carried onto a new mesh";
        break;
      }
      if (tags.empty() && step > 0) {  // a step without data: NaN everywhere
        v.times.push_back(time);
        v.steps.emplace_back(v.steps.empty() ? 0 : v.steps.back().size(),
                             std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      if (step == 0) {
        v.on_nodes = type == "NodeData";
        v.components = components > 0 ? components : 1;
      } else if ((type == "NodeData") != v.on_nodes || components != v.components) {
        kept = false;
        why = "its steps differ in kind or number of components";
        break;
      }
      const std::size_t n = v.on_nodes ? nv : live;
      const int k = v.components;
      std::vector<double> s(n * k, std::numeric_limits<double>::quiet_NaN());
      const auto& where = v.on_nodes ? vertex_of : cell_of;
      for (std::size_t i = 0; i < tags.size(); ++i) {
        auto it = where.find(tags[i]);
        if (it == where.end() || static_cast<int>(values[i].size()) < k) continue;
        ++on_mesh;
        for (int c = 0; c < k; ++c) s[it->second * k + c] = values[i][c];
      }
      v.times.push_back(time);
      v.steps.push_back(std::move(s));
    }
    if (kept && on_mesh == 0) {
      kept = false;
      why = "none of its values are on the mesh's nodes or " +
            std::string(three ? "tetrahedra" : "triangles");
    }
    if (!kept) {
      notes.push_back(label + " is not kept: " + why);
      continue;
    }
    out.push_back(std::move(v));
  }
  return out;
}

std::vector<int> add_data_views(const std::vector<DataView>& views,
                                const std::vector<std::size_t>& node_tags,
                                const std::vector<std::size_t>& cell_tags,
                                std::size_t nb_elements) {
  std::vector<int> tags;
  std::string model;
  gmsh::model::getCurrent(model);
  for (const DataView& v : views) {
    const int t = gmsh::view::add(v.name);
    tags.push_back(t);
    const std::vector<std::size_t>& where = v.on_nodes ? node_tags : cell_tags;
    for (std::size_t s = 0; s < v.steps.size(); ++s) {
      std::vector<std::size_t> ids;
      std::vector<std::vector<double>> data;
      const std::vector<double>& values = v.steps[s];
      if (!v.on_nodes && nb_elements > 0) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        data.assign(nb_elements, std::vector<double>(v.components, nan));
        for (std::size_t e = 0; e < nb_elements; ++e) ids.push_back(e + 1);
        for (std::size_t i = 0; i < where.size(); ++i)
          if (where[i] > 0 && where[i] <= nb_elements && (i + 1) * v.components <= values.size())
            data[where[i] - 1].assign(&values[i * v.components],
                                      &values[i * v.components] + v.components);
        gmsh::view::addModelData(t, static_cast<int>(s), model, "ElementData", ids, data,
                                 v.times[s], v.components);
        continue;
      }
      for (std::size_t i = 0; i < where.size(); ++i) {
        if (where[i] == 0 || (i + 1) * v.components > values.size()) continue;
        std::vector<double> x(&values[i * v.components], &values[i * v.components] + v.components);
        bool all_nan = true;
        for (double y : x) all_nan &= std::isnan(y);
        if (all_nan) continue;
        ids.push_back(where[i]);
        data.push_back(std::move(x));
      }
      if (ids.empty()) continue;
      gmsh::view::addModelData(t, static_cast<int>(s), model,
                               v.on_nodes ? "NodeData" : "ElementData", ids, data, v.times[s],
                               v.components);
    }
  }
  return tags;
}

}  // namespace cvtmesh
