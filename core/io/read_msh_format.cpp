#include "core/io/read_msh_format.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <string_view>

namespace cvtmesh {

MshFormat read_msh_format(const std::string& path) {
  MshFormat f;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int i = 0; i < 8 && std::getline(in, line); ++i) {
    if (line.rfind("$MeshFormat", 0) != 0) continue;
    int file_type = 0, data_size = 0;
    if (!(in >> f.version >> file_type >> data_size)) return MshFormat{};
    f.binary = file_type == 1;
    f.ok = true;
    return f;
  }
  return f;
}

int read_msh_partition_count(const std::string& path) {
  const MshFormat format = read_msh_format(path);
  if (!format.ok || format.version < 4) return 0;
  // The section comes after $Entities and before $Nodes (MSH 4.1): the head of the file only.
  std::ifstream in(path, std::ios::binary);
  std::string head;
  std::string chunk(1 << 16, '\0');
  const std::string section = "\n$PartitionedEntities";
  while (in && head.size() < (std::size_t{64} << 20)) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    head.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    const std::size_t at = head.find(section);
    if (at != std::string::npos) {
      in.read(chunk.data(), 64);  // the section's line and the count may straddle the chunk
      head.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
      std::size_t pos = head.find('\n', at + 1);
      if (pos == std::string::npos) return 0;
      ++pos;
      if (format.binary) {
        if (head.size() < pos + sizeof(std::uint64_t)) return 0;
        std::uint64_t n = 0;
        std::memcpy(&n, head.data() + pos, sizeof n);
        return n < (1u << 30) ? static_cast<int>(n) : 0;
      }
      long n = 0;
      for (; pos < head.size() && head[pos] >= '0' && head[pos] <= '9'; ++pos)
        n = std::min(10 * n + (head[pos] - '0'), 1L << 30);
      return static_cast<int>(n);
    }
    if (head.find("\n$Nodes") != std::string::npos) break;
  }
  return 0;
}

bool msh_repeats_identical_sections(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Each section: from its "$Name" line to its "$EndName" line, both at the start of a line.
  // Binary data may hold those bytes by chance: a wrong split only makes the copies differ.
  std::map<std::string, std::string_view> first;
  bool repeated = false;
  std::size_t pos = 0;
  while (pos < text.size()) {
    if (text[pos] == '$' && (pos == 0 || text[pos - 1] == '\n') &&
        text.compare(pos, 4, "$End") != 0) {
      const std::size_t eol = text.find_first_of("\r\n", pos);
      if (eol == std::string::npos) break;
      const std::string name = text.substr(pos + 1, eol - pos - 1);
      const std::string end = "\n$End" + name;
      const std::size_t stop = text.find(end, eol);
      if (stop == std::string::npos) return false;
      const std::string_view body(text.data() + eol, stop - eol);
      if (name != "MeshFormat" && name != "NodeData" && name != "ElementData" &&
          name != "ElementNodeData") {
        auto [it, fresh] = first.emplace(name, body);
        if (!fresh) {
          if (it->second != body) return false;
          repeated = true;
        }
      }
      pos = stop + end.size();
      continue;
    }
    const std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) break;
    pos = nl + 1;
  }
  return repeated;
}

}  // namespace cvtmesh
