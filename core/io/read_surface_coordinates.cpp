#include "core/io/read_surface_coordinates.h"

#include <array>
#include <cstdint>
#include <fstream>
#include <map>
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

// ASCII STL: OpenMesh merges the facets' corners that are equal in single precision, numbering
// the vertices in order of first appearance; the same order here, with each vertex's coordinates
// as first written in double precision. (Binary STL stores single precision: OpenMesh's are
// exact.)
std::vector<double> read_stl_ascii(std::istream& in) {
  std::string line, word;
  if (!std::getline(in, line)) return {};
  std::istringstream head(line);
  if (!(head >> word) || word != "solid") return {};
  std::map<std::array<float, 3>, int> seen;
  std::vector<double> xyz;
  while (std::getline(in, line)) {
    std::istringstream p(line);
    if (!(p >> word) || word != "vertex") continue;
    double x, y, z;
    if (!(p >> x >> y >> z)) return {};
    const std::array<float, 3> key{static_cast<float>(x), static_cast<float>(y),
                                   static_cast<float>(z)};
    if (seen.emplace(key, static_cast<int>(seen.size())).second) xyz.insert(xyz.end(), {x, y, z});
  }
  return xyz;
}

// PLY (ASCII or binary little-endian): the x, y, z properties of the vertex element, in file
// order (OpenMesh's), whatever their type; {} for anything else (big-endian, a list property in
// the vertex element, a vertex element after another).
std::vector<double> read_ply(std::istream& in) {
  std::string line, word;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0) return {};
  bool ascii = false, binary = false, in_vertex = false, vertex_first = false;
  long nv = -1;
  std::vector<std::pair<std::string, std::string>> props;  // type, name of the vertex element
  int elements = 0;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream h(line);
    if (!(h >> word)) continue;
    if (word == "format") {
      h >> word;
      ascii = word == "ascii";
      binary = word == "binary_little_endian";
    } else if (word == "element") {
      std::string name;
      h >> name;
      in_vertex = name == "vertex";
      if (in_vertex) {
        vertex_first = elements == 0;
        if (!(h >> nv)) return {};
      }
      ++elements;
    } else if (word == "property" && in_vertex) {
      std::string type, name;
      h >> type >> name;
      if (type == "list") return {};
      props.push_back({type, name});
    } else if (word == "end_header") {
      break;
    }
  }
  if (!(ascii || binary) || !vertex_first || nv <= 0) return {};
  int ix = -1, iy = -1, iz = -1;
  for (int i = 0; i < static_cast<int>(props.size()); ++i) {
    if (props[i].second == "x") ix = i;
    if (props[i].second == "y") iy = i;
    if (props[i].second == "z") iz = i;
  }
  if (ix < 0 || iy < 0 || iz < 0) return {};
  std::vector<double> xyz;
  xyz.reserve(3 * static_cast<std::size_t>(nv));
  std::vector<double> row(props.size());
  for (long v = 0; v < nv; ++v) {
    if (ascii) {
      if (!std::getline(in, line)) return {};
      std::istringstream p(line);
      for (double& x : row)
        if (!(p >> x)) return {};
    } else {
      for (std::size_t i = 0; i < props.size(); ++i) {
        const std::string& t = props[i].first;
        auto get = [&](auto value) {
          in.read(reinterpret_cast<char*>(&value), sizeof value);
          row[i] = static_cast<double>(value);
        };
        if (t == "double" || t == "float64")
          get(double{});
        else if (t == "float" || t == "float32")
          get(float{});
        else if (t == "int" || t == "int32")
          get(std::int32_t{});
        else if (t == "uint" || t == "uint32")
          get(std::uint32_t{});
        else if (t == "short" || t == "int16")
          get(std::int16_t{});
        else if (t == "ushort" || t == "uint16")
          get(std::uint16_t{});
        else if (t == "char" || t == "int8")
          get(std::int8_t{});
        else if (t == "uchar" || t == "uint8")
          get(std::uint8_t{});
        else
          return {};
      }
      if (!in) return {};
    }
    xyz.insert(xyz.end(), {row[ix], row[iy], row[iz]});
  }
  return xyz;
}

}  // namespace

std::vector<double> read_surface_coordinates(const std::string& path) {
  const std::string ext = file_extension(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  if (ext == ".off") return read_off(in);
  if (ext == ".obj") return read_obj(in);
  if (ext == ".stl") return read_stl_ascii(in);
  if (ext == ".ply") return read_ply(in);
  return {};
}

}  // namespace cvtmesh
