// Gmsh's node tags -> our dense ids. Tags are usually 1..N: a table then (no hashing: reading a
// 9M-tet mesh looked every element node up in a hash map, ~5 s of one thread); a hash map when
// they are sparse (max tag > 4 x the count + 1024).
#pragma once
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace cvtmesh {

class TagIndex {
 public:
  TagIndex(std::size_t max_tag, std::size_t count) {
    if (max_tag <= 4 * count + 1024)
      table_.assign(max_tag + 1, -1);
    else
      map_.reserve(2 * count);
  }
  // Gives `tag` the id `id`; false if it has one already (a duplicated tag).
  bool add(std::size_t tag, int id) {
    if (!table_.empty()) {
      if (tag >= table_.size()) table_.resize(tag + 1, -1);
      if (table_[tag] >= 0) return false;
      table_[tag] = id;
      return true;
    }
    return map_.emplace(tag, id).second;
  }
  // The id of `tag`, -1 if none.
  int find(std::size_t tag) const {
    if (!table_.empty()) return tag < table_.size() ? table_[tag] : -1;
    const auto it = map_.find(tag);
    return it == map_.end() ? -1 : it->second;
  }

 private:
  std::vector<int> table_;
  std::unordered_map<std::size_t, int> map_;
};

}  // namespace cvtmesh
