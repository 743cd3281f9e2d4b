// Order-independent keys for triangles and edges, for hashing faces and edges of flat meshes.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>

namespace cvtmesh {

using FaceKey = std::array<int, 3>;  // sorted vertex ids
using EdgeKey = std::array<int, 2>;  // sorted vertex ids

inline FaceKey face_key(int a, int b, int c) {
  FaceKey k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}
inline EdgeKey edge_key(int a, int b) {
  return a < b ? EdgeKey{a, b} : EdgeKey{b, a};
}

struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::uint64_t h = static_cast<std::uint32_t>(k[0]);
    h = h * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint32_t>(k[1]);
    h = h * 0x9E3779B97F4A7C15ULL ^ static_cast<std::uint32_t>(k[2]);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};
struct EdgeKeyHash {
  std::size_t operator()(const EdgeKey& k) const {
    std::uint64_t h = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(k[0])) << 32) |
                      static_cast<std::uint32_t>(k[1]);
    h *= 0x9E3779B97F4A7C15ULL;
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

}  // namespace cvtmesh
