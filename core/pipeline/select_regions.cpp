#include "core/pipeline/select_regions.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "core/pipeline/option_schema.h"

namespace cvtmesh {

std::vector<int> parse_region_tags(const std::string& regions) {
  std::vector<int> tags;
  std::size_t i = 0;
  auto bad = [&] {
    throw OptionError("regions", "'" + regions + "'",
                      "invalid value '" + regions +
                          "' for option regions (--regions): expected volume tags, e.g. 1,3");
  };
  while (i < regions.size()) {
    const char c = regions[i];
    if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    std::size_t j = i;
    if (regions[j] == '-' || regions[j] == '+') ++j;
    const std::size_t digits = j;
    while (j < regions.size() && std::isdigit(static_cast<unsigned char>(regions[j]))) ++j;
    if (j == digits || j - digits > 9) bad();
    if (j < regions.size() && regions[j] != ',' &&
        !std::isspace(static_cast<unsigned char>(regions[j])))
      bad();
    tags.push_back(std::stoi(regions.substr(i, j - i)));
    i = j;
  }
  return tags;
}

std::vector<int> select_regions(const TetMesh& mesh, const std::string& regions,
                                const std::string& physical) {
  std::set<int> present;
  for (int t = 0; t < mesh.nb_tets(); ++t)
    if (mesh.tets[4 * t] >= 0) present.insert(mesh.tet_region[t]);
  std::string available;
  for (int t : present) available += (available.empty() ? "" : ", ") + std::to_string(t);
  std::set<int> out;
  for (int t : parse_region_tags(regions)) {
    if (!present.count(t))
      throw OptionError("regions", std::to_string(t),
                        "invalid value " + std::to_string(t) +
                            " for option regions (--regions): no tetrahedra in volume " +
                            std::to_string(t) + " (available volumes: " + available + ")");
    out.insert(t);
  }
  if (!physical.empty()) {
    bool found = false;
    std::string names;
    for (const PhysicalGroup& g : mesh.model.groups) {
      if (g.dim != 3) continue;
      const std::string label = g.name.empty() ? std::to_string(g.tag) : g.name;
      names += (names.empty() ? "" : ", ") + ("'" + label + "'");
      if (g.name != physical && !(g.name.empty() && std::to_string(g.tag) == physical)) continue;
      found = true;
      for (int e : g.entities)
        if (present.count(e)) out.insert(e);
    }
    if (!found)
      throw OptionError("physical", "'" + physical + "'",
                        "invalid value '" + physical +
                            "' for option physical (--physical): no volume physical group of "
                            "that name (available: " +
                            (names.empty() ? std::string("none") : names) + ")");
  }
  return {out.begin(), out.end()};
}

}  // namespace cvtmesh
