#include "core/quality/quality_table.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <functional>
#include <nlohmann/json.hpp>

namespace cvtmesh {
namespace {

struct Row {
  std::string name;
  std::function<std::string(const QualityStats&)> cell;
};

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string count(long v) {
  return std::to_string(v);
}

// The rows, in the paper's order. 3D: Table 6/7 plus dihedral angles and radius ratio.
// 2D: Tables 1-5 (average quality, minimum quality, minimum angle, maximum angle).
std::vector<Row> rows_for(const std::vector<QualityStats>& cols) {
  const bool three_d = cols.empty() || cols.front().dim == 3;
  bool any_inverted = false;
  for (const auto& c : cols) any_inverted |= c.nb_inverted > 0;
  std::vector<Row> rows;
  rows.push_back(
      {"number of elements", [](const QualityStats& s) { return count(s.nb_elements); }});
  if (three_d) {
    rows.push_back({"0.7 < Q <= 1.0", [](const QualityStats& s) { return count(s.bin[0]); }});
    rows.push_back({"0.5 < Q <= 0.7", [](const QualityStats& s) { return count(s.bin[1]); }});
    rows.push_back({"0.3 < Q <= 0.5", [](const QualityStats& s) { return count(s.bin[2]); }});
    rows.push_back({"0.0 < Q <= 0.3", [](const QualityStats& s) { return count(s.bin[3]); }});
    if (any_inverted)
      rows.push_back(
          {"Q <= 0 (inverted/flat)", [](const QualityStats& s) { return count(s.nb_inverted); }});
    rows.push_back({"Q_min", [](const QualityStats& s) { return fmt("%.4f", s.q_min); }});
    rows.push_back(
        {"bad elements (%)", [](const QualityStats& s) { return fmt("%.2f", s.bad_pct); }});
    rows.push_back(
        {"good elements (%)", [](const QualityStats& s) { return fmt("%.2f", s.good_pct); }});
    rows.push_back({"average quality", [](const QualityStats& s) { return fmt("%.4f", s.q_avg); }});
    rows.push_back(
        {"min dihedral angle", [](const QualityStats& s) { return fmt("%.2f", s.min_angle); }});
    rows.push_back(
        {"max dihedral angle", [](const QualityStats& s) { return fmt("%.2f", s.max_angle); }});
    rows.push_back({"average radius ratio",
                    [](const QualityStats& s) { return fmt("%.4f", s.avg_radius_ratio); }});
  } else if (std::any_of(cols.begin(), cols.end(),
                         [](const QualityStats& c) { return c.nb_elements > 0; })) {
    // (A mesh of quadrangles only has no triangle rows: its quadrangle rows follow as extras.)
    if (any_inverted)
      rows.push_back({"inverted/flat", [](const QualityStats& s) { return count(s.nb_inverted); }});
    rows.push_back({"average quality", [](const QualityStats& s) { return fmt("%.4f", s.q_avg); }});
    rows.push_back({"minimum quality", [](const QualityStats& s) { return fmt("%.4f", s.q_min); }});
    rows.push_back(
        {"minimum angle", [](const QualityStats& s) { return fmt("%.2f", s.min_angle); }});
    rows.push_back(
        {"maximum angle", [](const QualityStats& s) { return fmt("%.2f", s.max_angle); }});
  }
  // The FE measures (fe_measures.h), when a column has them.
  bool any_fe = false;
  for (const auto& c : cols) any_fe |= c.fe_measured;
  if (any_fe) {
    auto fe = [](double (*f)(const QualityStats&), const char* format) {
      return [f, format](const QualityStats& s) {
        return s.fe_measured ? fmt(format, f(s)) : std::string("-");
      };
    };
    rows.push_back({"time step", fe([](const QualityStats& s) { return s.time_step; }, "%.3e")});
    rows.push_back({"element time step",
                    fe([](const QualityStats& s) { return s.element_time_step; }, "%.3e")});
    rows.push_back({"CG iterations", [](const QualityStats& s) {
                      return s.fe_measured ? count(s.cg_iterations) : std::string("-");
                    }});
    rows.push_back({"stiffness condition",
                    fe([](const QualityStats& s) { return s.stiffness_condition; }, "%.1f")});
  }
  // Extra rows: the union of the columns' extra names, in first-seen order.
  std::vector<std::string> extra;
  for (const auto& c : cols)
    for (const auto& [k, v] : c.extra)
      if (std::find(extra.begin(), extra.end(), k) == extra.end()) extra.push_back(k);
  for (const auto& name : extra)
    rows.push_back({name, [name](const QualityStats& s) {
                      for (const auto& [k, v] : s.extra)
                        if (k == name)
                          return v == static_cast<long>(v) && std::abs(v) < 1e12
                                     ? count(static_cast<long>(v))
                                     : fmt("%.3f", v);
                      return std::string("-");
                    }});
  return rows;
}

}  // namespace

std::string QualityTable::to_text() const {
  const auto rows = rows_for(columns);
  std::size_t w0 = 0;
  for (const auto& r : rows) w0 = std::max(w0, r.name.size());
  std::vector<std::size_t> w(columns.size());
  for (std::size_t c = 0; c < columns.size(); ++c) {
    w[c] = columns[c].label.size();
    for (const auto& r : rows) w[c] = std::max(w[c], r.cell(columns[c]).size());
  }
  std::string out;
  auto pad_left = [](const std::string& s, std::size_t n) {
    return std::string(n - s.size(), ' ') + s;
  };
  auto pad_right = [](const std::string& s, std::size_t n) {
    return s + std::string(n - s.size(), ' ');
  };
  out += pad_right("", w0);
  for (std::size_t c = 0; c < columns.size(); ++c) out += "  " + pad_left(columns[c].label, w[c]);
  out += "\n";
  for (const auto& r : rows) {
    out += pad_right(r.name, w0);
    for (std::size_t c = 0; c < columns.size(); ++c)
      out += "  " + pad_left(r.cell(columns[c]), w[c]);
    out += "\n";
  }
  return out;
}

std::string QualityTable::to_markdown() const {
  const auto rows = rows_for(columns);
  std::string out = "| |";
  for (const auto& c : columns) out += " " + c.label + " |";
  out += "\n|---|";
  for (std::size_t c = 0; c < columns.size(); ++c) out += "---:|";
  out += "\n";
  for (const auto& r : rows) {
    out += "| " + r.name + " |";
    for (const auto& c : columns) out += " " + r.cell(c) + " |";
    out += "\n";
  }
  return out;
}

std::string QualityTable::to_json() const {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const auto& s : columns) {
    nlohmann::ordered_json c;
    c["label"] = s.label;
    c["dim"] = s.dim;
    c["number_of_elements"] = s.nb_elements;
    if (s.dim == 3) {
      c["q_0.7_1.0"] = s.bin[0];
      c["q_0.5_0.7"] = s.bin[1];
      c["q_0.3_0.5"] = s.bin[2];
      c["q_0.0_0.3"] = s.bin[3];
    }
    c["inverted"] = s.nb_inverted;
    c["q_min"] = s.q_min;
    c["q_max"] = s.q_max;
    c["bad_elements_pct"] = s.bad_pct;
    c["good_elements_pct"] = s.good_pct;
    c["average_quality"] = s.q_avg;
    c[s.dim == 3 ? "min_dihedral_angle" : "minimum_angle"] = s.min_angle;
    c[s.dim == 3 ? "max_dihedral_angle" : "maximum_angle"] = s.max_angle;
    c["average_radius_ratio"] = s.avg_radius_ratio;
    // null when not measured (fe_measures.h: off, or above the automatic size limit).
    auto fe = [&](double v) { return s.fe_measured ? nlohmann::ordered_json(v) : nullptr; };
    c["time_step"] = fe(s.time_step);
    c["element_time_step"] = fe(s.element_time_step);
    c["cg_iterations"] =
        s.fe_measured ? nlohmann::ordered_json(s.cg_iterations) : nlohmann::ordered_json(nullptr);
    c["stiffness_condition"] = fe(s.stiffness_condition);
    // The extra rows under snake_case keys as the others ("quad scaled Jacobian min" ->
    // "quad_scaled_jacobian_min").
    for (const auto& [k, v] : s.extra) {
      std::string key = k;
      for (char& ch : key)
        ch = ch == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
      c[key] = v;
    }
    j.push_back(c);
  }
  return j.dump(2) + "\n";
}

}  // namespace cvtmesh
