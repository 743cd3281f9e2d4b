#include "core/distributed/part_exchange.h"

#include <cstdint>
#include <cstring>
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

}  // namespace

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
