#include "core/io/read_msh2_periodic.h"

#include <fstream>
#include <sstream>

#include "core/util/error.h"

namespace cvtmesh {

std::vector<PeriodicLink> read_msh2_periodic(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::vector<PeriodicLink> links;
  std::string line;
  long number = 0;
  while (std::getline(f, line)) {
    ++number;
    if (line.rfind("$Periodic", 0) == 0) break;
  }
  if (!f) return links;
  auto fail = [&](const std::string& what) {
    throw InputError("'" + path + "': malformed $Periodic section at line " +
                     std::to_string(number) + ": " + what);
  };
  auto next = [&]() -> std::istringstream {
    if (!std::getline(f, line)) fail("the file ends inside it");
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return std::istringstream(line);
  };
  long nb_links = -1;
  if (!(next() >> nb_links) || nb_links < 0 || nb_links > 1000000) fail("expected the link count");
  for (long i = 0; i < nb_links; ++i) {
    PeriodicLink l;
    if (!(next() >> l.dim >> l.tag >> l.master) || l.dim < 0 || l.dim > 3)
      fail("expected 'dim tag masterTag'");
    std::istringstream s = next();
    std::string word;
    long nb_nodes = -1;
    if (line.rfind("Affine", 0) == 0) {
      s >> word;
      double a;
      while (s >> a) l.affine.push_back(a);
      if (l.affine.size() != 16) fail("expected 16 affine coefficients");
      s = next();
    }
    if (!(s >> nb_nodes) || nb_nodes < 0 || nb_nodes > 100000000) fail("expected the node count");
    for (long k = 0; k < nb_nodes; ++k) {
      long long a = 0, b = 0;
      if (!(next() >> a >> b) || a <= 0 || b <= 0) fail("expected 'node masterNode' tags");
      l.node_tags.push_back(static_cast<std::size_t>(a));
      l.master_node_tags.push_back(static_cast<std::size_t>(b));
    }
    if (!l.node_tags.empty() && l.master != l.tag) links.push_back(std::move(l));
  }
  if (!std::getline(f, line) || line.rfind("$EndPeriodic", 0) != 0) fail("expected $EndPeriodic");
  return links;
}

}  // namespace cvtmesh
