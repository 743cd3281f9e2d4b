// Faces bucketed by their smallest id (core/mesh/face_buckets.h): every face in its smallest id's
// bucket, each bucket sorted by (b, c, id), so that equal faces are adjacent and in increasing
// id; dead faces left out; edges (c = 0) as well as triangles. Checked against a plain sort.
#include "core/mesh/face_buckets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <tuple>
#include <vector>

namespace cvtmesh {
namespace {

TEST(FaceBuckets, EqualFacesAdjacentInIdOrderAsASortWould) {
  for (const int nodes : {2, 3}) {
    std::mt19937 rng(11 + nodes);
    const std::uint32_t nb_ids = 40;
    std::uniform_int_distribution<std::uint32_t> id(0, nb_ids - 1);
    // Faces with repeats (few ids: many equal faces), given in any vertex order; every 7th dead.
    std::vector<std::array<std::uint32_t, 3>> faces(3000);
    for (auto& f : faces) f = {id(rng), id(rng), nodes == 3 ? id(rng) : 0};
    auto face = [&](std::size_t i, std::uint32_t* k) {
      if (i % 7 == 3) return false;
      std::copy(faces[i].begin(), faces[i].begin() + nodes, k);
      std::sort(k, k + nodes);
      if (nodes == 2) k[2] = 0;
      return true;
    };
    const FaceBuckets fb = bucket_faces(nb_ids, faces.size(), face);
    // The expected order: (smallest, b, c, id) sorted.
    std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t>> want;
    for (std::size_t i = 0; i < faces.size(); ++i) {
      std::uint32_t k[3];
      if (face(i, k)) want.emplace_back(k[0], k[1], k[2], static_cast<std::uint32_t>(i));
    }
    std::sort(want.begin(), want.end());
    ASSERT_EQ(fb.nb_buckets(), nb_ids);
    ASSERT_EQ(fb.records.size(), want.size());
    std::size_t n = 0;
    for (std::uint32_t a = 0; a < nb_ids; ++a)
      for (const FaceRecord* r = fb.begin_of(a); r != fb.end_of(a); ++r, ++n)
        EXPECT_EQ(std::make_tuple(a, r->b, r->c, r->id), want[n]);
    EXPECT_EQ(n, want.size());
  }
}

}  // namespace
}  // namespace cvtmesh
