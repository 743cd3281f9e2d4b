// Equal faces made adjacent without hashing: each face's sorted vertex ids a <= b <= c (an edge:
// a <= b, c = 0) as a record (b, c, id) in the bucket of its smallest id a (a counting sort), each
// bucket then sorted by (b, c, id) (the buckets in parallel). O(#faces + #ids) plus small sorts;
// at 1M tets ~3x faster than one hash map of the 4M faces. build_adjacency (the faces of the tets)
// and add_missing_facets (the facets of Gmsh's cells) match faces with it.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cvtmesh {

struct FaceRecord {
  std::uint32_t b, c;  // the face's two larger ids (c = 0 for an edge)
  std::uint32_t id;    // the caller's number of the face
};

inline bool operator<(const FaceRecord& x, const FaceRecord& y) {
  return x.b != y.b ? x.b < y.b : x.c != y.c ? x.c < y.c : x.id < y.id;
}

// Two records of one bucket are the same face.
inline bool same_face(const FaceRecord& x, const FaceRecord& y) {
  return x.b == y.b && x.c == y.c;
}

struct FaceBuckets {
  std::vector<std::size_t> start;  // #ids + 1: bucket a is records[start[a] .. start[a + 1])
  std::vector<FaceRecord> records;
  std::size_t nb_buckets() const { return start.empty() ? 0 : start.size() - 1; }
  const FaceRecord* begin_of(std::size_t a) const { return records.data() + start[a]; }
  const FaceRecord* end_of(std::size_t a) const { return records.data() + start[a + 1]; }
};

// Sorts every bucket by (b, c, id), in parallel.
void sort_face_buckets(FaceBuckets& buckets);

// face(i, k) (0 <= i < nb_faces) returns false if there is no face i (a dead tet), else writes its
// sorted ids (< nb_ids) to k[0..2] (k[2] = 0 for an edge); it is called twice per face. The ids i
// must fit 32 bits.
template <class Face>
FaceBuckets bucket_faces(std::size_t nb_ids, std::size_t nb_faces, Face face) {
  FaceBuckets fb;
  fb.start.assign(nb_ids + 1, 0);
  std::uint32_t k[3];
  for (std::size_t i = 0; i < nb_faces; ++i)
    if (face(i, k)) ++fb.start[k[0] + 1];
  for (std::size_t a = 0; a < nb_ids; ++a) fb.start[a + 1] += fb.start[a];
  fb.records.resize(fb.start[nb_ids]);
  std::vector<std::size_t> fill(fb.start.begin(), fb.start.end() - 1);
  for (std::size_t i = 0; i < nb_faces; ++i)
    if (face(i, k)) fb.records[fill[k[0]]++] = {k[1], k[2], static_cast<std::uint32_t>(i)};
  sort_face_buckets(fb);
  return fb;
}

}  // namespace cvtmesh
