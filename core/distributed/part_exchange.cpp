#include "core/distributed/part_exchange.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>

#include "core/util/error.h"

namespace cvtmesh {

namespace {

template <class T>
void put(const std::vector<T>& v, std::vector<char>& out) {
  static_assert(std::is_trivially_copyable_v<T>);
  const std::uint64_t n = v.size();
  const char* p = reinterpret_cast<const char*>(&n);
  out.insert(out.end(), p, p + sizeof n);
  const char* d = reinterpret_cast<const char*>(v.data());
  out.insert(out.end(), d, d + n * sizeof(T));
}

template <class T>
void get(const std::vector<char>& in, std::size_t& pos, std::vector<T>& v) {
  std::uint64_t n = 0;
  if (in.size() < pos + sizeof n) throw InvariantError("unpack_part: the buffer is too short");
  std::memcpy(&n, in.data() + pos, sizeof n);
  pos += sizeof n;
  if (n > (in.size() - pos) / sizeof(T))
    throw InvariantError("unpack_part: the buffer is too short");
  v.resize(n);
  std::memcpy(static_cast<void*>(v.data()), in.data() + pos, n * sizeof(T));
  pos += n * sizeof(T);
}

template <class T>
void put_value(const T& x, std::vector<char>& out) {
  static_assert(std::is_trivially_copyable_v<T>);
  const char* p = reinterpret_cast<const char*>(&x);
  out.insert(out.end(), p, p + sizeof x);
}

template <class T>
void get_value(const std::vector<char>& in, std::size_t& pos, T& x) {
  if (in.size() < pos + sizeof x) throw InvariantError("unpack_part: the buffer is too short");
  std::memcpy(static_cast<void*>(&x), in.data() + pos, sizeof x);
  pos += sizeof x;
}

void put_string(const std::string& s, std::vector<char>& out) {
  put(std::vector<char>(s.begin(), s.end()), out);
}

void get_string(const std::vector<char>& in, std::size_t& pos, std::string& s) {
  std::vector<char> c;
  get(in, pos, c);
  s.assign(c.begin(), c.end());
}

// The count of a list, checked against what is left of the buffer (each item takes at least
// `min_bytes`).
std::uint64_t get_count(const std::vector<char>& in, std::size_t& pos, std::size_t min_bytes) {
  std::uint64_t n = 0;
  get_value(in, pos, n);
  if (n > (in.size() - pos) / min_bytes)
    throw InvariantError("unpack_part: the buffer is too short");
  return n;
}

}  // namespace

std::vector<char> PartExchange::broadcast(const std::vector<char>& from_root) {
  return all_gather(rank() == 0 ? from_root : std::vector<char>{}).at(0);
}

std::vector<char> PartExchange::scatter(const std::vector<std::vector<char>>& per_rank) {
  // Rank 0's buffers, concatenated with their sizes, to every rank: each reads its own.
  std::vector<char> all;
  if (rank() == 0) {
    if (static_cast<int>(per_rank.size()) != size())
      throw InvariantError("PartExchange::scatter: one buffer per rank expected");
    for (const auto& b : per_rank) put(b, all);
  }
  const std::vector<char> got = broadcast(all);
  std::size_t pos = 0;
  std::vector<char> mine;
  for (int k = 0; k <= rank(); ++k) get(got, pos, mine);
  return mine;
}

std::vector<std::vector<char>> PartExchange::gather(const std::vector<char>& mine) {
  std::vector<std::vector<char>> all = all_gather(mine);
  if (rank() != 0) all.clear();
  return all;
}

void pack_model(const ModelInfo& m, std::vector<char>& out) {
  put_string(m.name, out);
  put_string(m.source, out);
  put_value(static_cast<std::uint64_t>(m.entities.size()), out);
  for (const ModelEntity& e : m.entities) {
    put_value(e.dim, out);
    put_value(e.tag, out);
    put(e.boundary, out);
  }
  put_value(static_cast<std::uint64_t>(m.groups.size()), out);
  for (const PhysicalGroup& g : m.groups) {
    put_value(g.dim, out);
    put_value(g.tag, out);
    put_string(g.name, out);
    put(g.entities, out);
  }
  put_value(static_cast<int>(m.origin), out);
  put(m.file_blocks, out);
  put_value(m.high_order.order, out);
}

void unpack_model(const std::vector<char>& in, std::size_t& pos, ModelInfo& m) {
  m = ModelInfo{};
  get_string(in, pos, m.name);
  get_string(in, pos, m.source);
  m.entities.resize(get_count(in, pos, 2 * sizeof(int) + 8));
  for (ModelEntity& e : m.entities) {
    get_value(in, pos, e.dim);
    get_value(in, pos, e.tag);
    get(in, pos, e.boundary);
  }
  m.groups.resize(get_count(in, pos, 2 * sizeof(int) + 16));
  for (PhysicalGroup& g : m.groups) {
    get_value(in, pos, g.dim);
    get_value(in, pos, g.tag);
    get_string(in, pos, g.name);
    get(in, pos, g.entities);
  }
  int origin = 0;
  get_value(in, pos, origin);
  if (origin < 0 || origin > static_cast<int>(ElementOrigin::kMeshFile))
    throw InvariantError("unpack_model: corrupt buffer");
  m.origin = static_cast<ElementOrigin>(origin);
  get(in, pos, m.file_blocks);
  get_value(in, pos, m.high_order.order);
}

void pack_blocks(const std::vector<ElementBlock>& blocks, std::vector<char>& out) {
  put_value(static_cast<std::uint64_t>(blocks.size()), out);
  for (const ElementBlock& b : blocks) {
    put_value(b.dim, out);
    put_value(b.entity, out);
    put_value(b.gmsh_type, out);
    put(b.tags, out);
    put(b.nodes, out);
    put(b.medit_refs, out);
  }
}

void unpack_blocks(const std::vector<char>& in, std::size_t& pos,
                   std::vector<ElementBlock>& blocks) {
  blocks.resize(get_count(in, pos, 3 * sizeof(int) + 24));
  for (ElementBlock& b : blocks) {
    get_value(in, pos, b.dim);
    get_value(in, pos, b.entity);
    get_value(in, pos, b.gmsh_type);
    get(in, pos, b.tags);
    get(in, pos, b.nodes);
    get(in, pos, b.medit_refs);
  }
}

void pack_part(const TetMesh& m, std::vector<char>& out) {
  put(m.xyz, out);
  put(m.vclass, out);
  put(m.node_tags, out);
  put(m.tets, out);
  put(m.tet_region, out);
  put(m.tet_tags, out);
  put(m.tris, out);
  put(m.tri_surface, out);
  put(m.tri_tags, out);
}

void unpack_part(const std::vector<char>& in, std::size_t& pos, TetMesh& m) {
  get(in, pos, m.xyz);
  get(in, pos, m.vclass);
  get(in, pos, m.node_tags);
  get(in, pos, m.tets);
  get(in, pos, m.tet_region);
  get(in, pos, m.tet_tags);
  get(in, pos, m.tris);
  get(in, pos, m.tri_surface);
  get(in, pos, m.tri_tags);
  m.adj.clear();
  if (m.xyz.size() % 3 || m.vclass.size() * 3 != m.xyz.size() || m.tets.size() % 4 ||
      m.tet_region.size() * 4 != m.tets.size() || m.tris.size() % 3 ||
      m.tri_surface.size() * 3 != m.tris.size())
    throw InvariantError("unpack_part: inconsistent array sizes");
}

}  // namespace cvtmesh
