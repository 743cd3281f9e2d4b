#include "convert/json_report.h"

#include <cmath>

namespace cvtmesh::cli {
namespace {

// Keys whose values are counts (integers in the JSON) wherever they come from.
bool is_count(const std::string& key) {
  return key == "iterations" || key == "number_of_elements" || key == "inverted" ||
         key.rfind("q_", 0) == 0 || key.rfind("nb_", 0) == 0 || key.rfind("number_of_", 0) == 0;
}

void integers_as_integers(nlohmann::ordered_json& o) {
  for (auto it = o.begin(); it != o.end(); ++it) {
    if (!it.value().is_number_float() || !is_count(it.key())) continue;
    const double v = it.value().get<double>();
    if (std::isfinite(v) && v == std::floor(v)) it.value() = static_cast<long long>(v);
  }
}

}  // namespace

nlohmann::ordered_json mesh_json(const QualityStats& s) {
  QualityTable one;
  one.columns = {s};
  nlohmann::ordered_json c = nlohmann::ordered_json::parse(one.to_json()).at(0);
  nlohmann::ordered_json out;
  const bool d3 = s.dim == 3;
  for (auto it = c.begin(); it != c.end(); ++it) {
    std::string key = it.key();
    if (key == "min_dihedral_angle" || key == "minimum_angle") key = "min_angle";
    if (key == "max_dihedral_angle" || key == "maximum_angle") key = "max_angle";
    out[key] = it.value();
    if (key == "number_of_elements") {
      // The paper's four bins of Q, in both dimensions.
      out["q_0.7_1.0"] = s.bin[0];
      out["q_0.5_0.7"] = s.bin[1];
      out["q_0.3_0.5"] = s.bin[2];
      out["q_0.0_0.3"] = s.bin[3];
    }
  }
  out["angle"] = d3 ? "dihedral" : "planar";
  integers_as_integers(out);
  return out;
}

nlohmann::ordered_json table_json(const QualityTable& t) {
  nlohmann::ordered_json j;
  j["schema"] = kJsonSchema;
  j["meshes"] = nlohmann::ordered_json::array();
  for (const auto& s : t.columns) j["meshes"].push_back(mesh_json(s));
  return j;
}

nlohmann::ordered_json optimize_json(const OptimizeResult& r, const std::string& requested_method,
                                     const std::string& input, const std::string& output) {
  nlohmann::ordered_json j;
  j["schema"] = kJsonSchema;
  j["command"] = "optimize";
  j["input"] = input;
  j["output"] = output;
  j["method"] = r.method;
  j["requested_method"] = requested_method.empty() ? r.method : requested_method;
  j["iterations"] = r.iterations;
  j["converged"] = r.converged;
  j["kept_input"] = r.kept_input;
  j["seconds"] = r.seconds;
  j["notes"] = r.notes;
  QualityStats before = r.before, after = r.after;
  before.label = "input";
  after.label = r.method;
  j["before"] = mesh_json(before);
  j["after"] = mesh_json(after);
  return j;
}

}  // namespace cvtmesh::cli
