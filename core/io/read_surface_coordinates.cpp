#include "core/io/read_surface_coordinates.h"

#include <fstream>
#include <sstream>

#include "core/io/read_mesh.h"

namespace cvtmesh {
namespace {

// The next line that is neither empty nor a comment.
bool next_line(std::istream& in, std::string& line) {
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    return true;
  }
  return false;
}

std::vector<double> read_off(std::istream& in) {
  std::string line;
  if (!next_line(in, line)) return {};
  std::istringstream head(line);
  std::string magic;
  head >> magic;
  if (magic != "OFF") return {};  // COFF, NOFF, 4OFF, binary OFF...: OpenMesh's
  long nv = -1, nf = -1;
  if (!(head >> nv >> nf)) {
    if (!next_line(in, line)) return {};
    std::istringstream counts(line);
    if (!(counts >> nv >> nf)) return {};
  }
  if (nv <= 0) return {};
  std::vector<double> xyz;
  xyz.reserve(3 * static_cast<std::size_t>(nv));
  for (long v = 0; v < nv; ++v) {
    if (!next_line(in, line)) return {};
    std::istringstream p(line);
    double x, y, z;
    if (!(p >> x >> y >> z)) return {};
    xyz.insert(xyz.end(), {x, y, z});
  }
  return xyz;
}

std::vector<double> read_obj(std::istream& in) {
  std::vector<double> xyz;
  std::string line;
  while (std::getline(in, line)) {
    if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
    std::istringstream p(line.substr(2));
    double x, y, z;
    if (!(p >> x >> y >> z)) return {};
    xyz.insert(xyz.end(), {x, y, z});
  }
  return xyz;
}

}  // namespace

std::vector<double> read_surface_coordinates(const std::string& path) {
  const std::string ext = file_extension(path);
  std::ifstream in(path);
  if (!in) return {};
  if (ext == ".off") return read_off(in);
  if (ext == ".obj") return read_obj(in);
  return {};
}

}  // namespace cvtmesh
