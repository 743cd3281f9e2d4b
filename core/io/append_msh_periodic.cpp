#include "core/io/append_msh_periodic.h"

#include <cstdio>
#include <fstream>

#include "core/util/error.h"

namespace cvtmesh {

void append_msh_periodic(const std::string& path, const std::vector<PeriodicLink>& links,
                         double msh_version, bool binary) {
  // MSH 2.2 as Gmsh 4.8 writes it: after $Elements, in text even in a binary file (read back by
  // read_msh2_periodic: Gmsh's API does not give it).
  if (links.empty()) return;
  std::ofstream f(path, std::ios::binary | std::ios::app);
  if (!f) throw OutputError("cannot write '" + path + "': cannot append the $Periodic section");
  auto text = [&](const std::string& s) {
    f.write(s.data(), static_cast<std::streamsize>(s.size()));
  };
  char buf[64];
  auto num = [&](double x) {
    std::snprintf(buf, sizeof buf, "%.16g", x);
    return std::string(buf);
  };
  text("$Periodic\n");
  if (binary && msh_version > 3) {
    auto put = [&](const auto& v) { f.write(reinterpret_cast<const char*>(&v), sizeof v); };
    put(static_cast<std::size_t>(links.size()));
    for (const PeriodicLink& l : links) {
      put(static_cast<int>(l.dim));
      put(static_cast<int>(l.tag));
      put(static_cast<int>(l.master));
      put(static_cast<std::size_t>(l.affine.size()));
      for (double a : l.affine) put(a);
      put(static_cast<std::size_t>(l.node_tags.size()));
      for (std::size_t i = 0; i < l.node_tags.size(); ++i) {
        put(l.node_tags[i]);
        put(l.master_node_tags[i]);
      }
    }
    text("\n");
  } else {
    text(std::to_string(links.size()) + "\n");
    for (const PeriodicLink& l : links) {
      text(std::to_string(l.dim) + " " + std::to_string(l.tag) + " " + std::to_string(l.master) +
           "\n");
      if (msh_version > 3) {
        std::string line = std::to_string(l.affine.size());
        for (double a : l.affine) line += " " + num(a);
        text(line + "\n");
      } else if (!l.affine.empty()) {
        std::string line = "Affine";
        for (double a : l.affine) line += " " + num(a);
        text(line + "\n");
      }
      text(std::to_string(l.node_tags.size()) + "\n");
      for (std::size_t i = 0; i < l.node_tags.size(); ++i)
        text(std::to_string(l.node_tags[i]) + " " + std::to_string(l.master_node_tags[i]) + "\n");
    }
  }
  text("$EndPeriodic\n");
  f.close();
  if (!f) throw OutputError("cannot write '" + path + "': cannot append the $Periodic section");
}

}  // namespace cvtmesh
