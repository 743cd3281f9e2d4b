// optimize_partitioned: parts optimized alone with their interfaces pinned, put back, the cut moved
// between rounds; the result valid, the boundary kept, no interior vertex frozen throughout, and
// the same mesh whatever the number of ranks.
#include "core/distributed/optimize_partitioned.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <condition_variable>
#include <mutex>
#include <set>
#include <thread>

#include "core/mesh/check_mesh.h"
#include "core/mesh/extract_regions.h"
#include "core/mesh/face_key.h"
#include "core/mesh/merge_regions.h"
#include "core/util/error.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

std::multiset<FaceKey> boundary_faces(const TetMesh& m) {
  std::multiset<FaceKey> s;
  for (int f = 0; f < m.nb_tris(); ++f)
    s.insert(face_key(m.tris[3 * f], m.tris[3 * f + 1], m.tris[3 * f + 2]));
  return s;
}

// `n` ranks as threads of this process: all_gather waits for every rank's buffer.
class ThreadRanks {
 public:
  explicit ThreadRanks(int n) : n_(n), slots_(n) {}
  std::vector<std::vector<char>> gather(int rank, const std::vector<char>& mine) {
    std::unique_lock<std::mutex> lock(m_);
    const long generation = generation_;
    slots_[rank] = mine;
    if (++arrived_ == n_) {
      result_ = slots_;
      arrived_ = 0;
      ++generation_;
      cv_.notify_all();
    } else {
      cv_.wait(lock, [&] { return generation_ != generation; });
    }
    return result_;
  }
  int size() const { return n_; }

 private:
  int n_, arrived_ = 0;
  long generation_ = 0;
  std::vector<std::vector<char>> slots_, result_;
  std::mutex m_;
  std::condition_variable cv_;
};

class ThreadExchange : public PartExchange {
 public:
  ThreadExchange(ThreadRanks& ranks, int rank) : ranks_(ranks), rank_(rank) {}
  int rank() const override { return rank_; }
  int size() const override { return ranks_.size(); }
  std::vector<std::vector<char>> all_gather(const std::vector<char>& mine) override {
    return ranks_.gather(rank_, mine);
  }

 private:
  ThreadRanks& ranks_;
  int rank_;
};

TEST(OptimizePartitioned, ValidBoundaryKeptBetterAndNoInteriorVertexFrozenInEveryRound) {
  const TetMesh input = testing::cube_sphere(0.12, 0.1).tet;
  TetMesh m = input;
  SerialExchange serial;
  OptimizeOptions fixed;
  fixed.fix_boundary = true;
  const PartitionedResult r = optimize_partitioned(m, fixed, {2, 2}, serial);
  ASSERT_EQ(r.rounds.size(), 2u);
  EXPECT_FALSE(r.kept_input);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems.front());
  EXPECT_EQ(boundary_faces(m), boundary_faces(input));  // same vertex ids: the boundary's kept
  for (int v = 0; v < input.nb_vertices(); ++v)
    if (input.vclass[v].dim < 3)
      EXPECT_TRUE(std::equal(m.point(v), m.point(v) + 3, input.point(v))) << v;
  for (const PartitionRound& pr : r.rounds) {
    EXPECT_EQ(pr.part_tets.size(), 2u);
    EXPECT_GT(pr.nb_interface, 0);
  }
  EXPECT_EQ(r.rounds[1].nb_avoided_cut, 0);
  EXPECT_EQ(r.nb_frozen_every_round, 0);
  EXPECT_GT(r.after.q_min, r.before.q_min);
  EXPECT_GT(r.after.q_avg, r.before.q_avg);
  EXPECT_GT(r.after.min_angle, r.before.min_angle);
  // One round leaves the interface frozen: the count says so.
  TetMesh once = input;
  EXPECT_GT(optimize_partitioned(once, fixed, {2, 1}, serial).nb_frozen_every_round, 0);
}

// The default free boundary in each part: boundary vertices move, but stay on the model (the
// unit cube's faces or the sphere of radius 0.25 at its centre) within the Hausdorff bound, the
// interfaces between parts still fit (check_mesh), and the result beats the fixed-boundary one.
TEST(OptimizePartitioned, FreeBoundaryMovesOnTheModelWithinTheBound) {
  const TetMesh input = testing::cube_sphere(0.12, 0.1).tet;
  TetMesh free_mesh = input, fixed_mesh = input;
  SerialExchange serial;
  OptimizeOptions fixed;
  fixed.fix_boundary = true;
  const PartitionedResult rf = optimize_partitioned(free_mesh, OptimizeOptions{}, {3, 2}, serial);
  const PartitionedResult rx = optimize_partitioned(fixed_mesh, fixed, {3, 2}, serial);
  EXPECT_FALSE(rf.kept_input);
  const MeshCheck c = check_mesh(free_mesh);
  EXPECT_TRUE(c.ok) << (c.problems.empty() ? "" : c.problems.front());
  const double bound = 2e-3 * std::sqrt(3.0);  // 2e-3 of the unit cube's diagonal
  int moved = 0;
  std::vector<char> on_boundary(free_mesh.nb_vertices(), 0);
  for (int v : free_mesh.tris) on_boundary[v] = 1;
  for (int v = 0; v < free_mesh.nb_vertices(); ++v) {
    if (!on_boundary[v]) continue;
    const double* p = free_mesh.point(v);
    double d = std::abs(std::hypot(p[0] - 0.5, p[1] - 0.5, p[2] - 0.5) - 0.25);
    for (int k = 0; k < 3; ++k) d = std::min({d, std::abs(p[k]), std::abs(1 - p[k])});
    EXPECT_LE(d, bound) << v;
    moved += v < input.nb_vertices() && !std::equal(p, p + 3, input.point(v));
  }
  EXPECT_GT(moved, 0);
  EXPECT_GT(rf.after.q_avg, rx.after.q_avg);
  EXPECT_GE(rf.after.q_min, rf.before.q_min);
}

TEST(OptimizePartitioned, TwoRanksGiveTheSameMeshAsOne) {
  const TetMesh input = testing::cube_sphere(0.15, 0.12).tet;
  OptimizeOptions o;
  o.method = "cvdt+swap";
  TetMesh one = input;
  SerialExchange serial;
  optimize_partitioned(one, o, {3, 2}, serial);
  // Rank 0 holds the mesh; rank 1 only gets its parts (its own mesh is empty, and stays so).
  ThreadRanks ranks(2);
  std::vector<TetMesh> out{input, TetMesh{}};
  std::vector<std::thread> threads;
  for (int k = 0; k < 2; ++k)
    threads.emplace_back([&, k] {
      ThreadExchange ex(ranks, k);
      optimize_partitioned(out[k], o, {3, 2}, ex);
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(out[0].xyz, one.xyz);
  EXPECT_EQ(out[0].tets, one.tets);
  EXPECT_EQ(out[0].tris, one.tris);
  EXPECT_EQ(out[1].nb_tets(), 0);
  EXPECT_EQ(out[1].nb_vertices(), 0);
}

TEST(OptimizePartitioned, RefusesASelectionOfVolumesAndBadCounts) {
  TetMesh m = testing::cube6();
  SerialExchange serial;
  OptimizeOptions o;
  o.regions = "1";
  EXPECT_THROW(optimize_partitioned(m, o, {2, 2}, serial), InputError);
  EXPECT_THROW(optimize_partitioned(m, OptimizeOptions{}, {0, 2}, serial), InputError);
  EXPECT_THROW(optimize_partitioned(m, OptimizeOptions{}, {2, 0}, serial), InputError);
  EXPECT_THROW(optimize_partitioned(m, OptimizeOptions{}, {7, 1}, serial), InputError);
}

TEST(MergeParts, PartsPutBackUnchangedGiveTheSameTetsAndOverlapsAreRefused) {
  TetMesh m = testing::cube_sphere(0.2, 0.15).tet;
  std::vector<RegionSubmesh> xs;
  for (int p = 0; p < 3; ++p) {
    std::vector<char> sel(m.nb_tets(), 0);
    for (int t = 0; t < m.nb_tets(); ++t) sel[t] = t % 3 == p;
    xs.push_back(extract_tets(m, sel));
    EXPECT_TRUE(check_mesh(xs.back().mesh).ok);
  }
  TetMesh back = m;
  merge_parts(back, {&xs[0], &xs[1], &xs[2]}, {&xs[0].mesh, &xs[1].mesh, &xs[2].mesh});
  EXPECT_EQ(back.xyz, m.xyz);
  EXPECT_TRUE(check_mesh(back).ok);
  auto tets_of = [](const TetMesh& x) {
    std::multiset<std::array<int, 4>> s;
    for (int t = 0; t < x.nb_tets(); ++t) {
      std::array<int, 4> q{x.tets[4 * t], x.tets[4 * t + 1], x.tets[4 * t + 2], x.tets[4 * t + 3]};
      std::sort(q.begin(), q.end());
      s.insert(q);
    }
    return s;
  };
  EXPECT_EQ(tets_of(back), tets_of(m));
  TetMesh again = m;
  EXPECT_THROW(merge_parts(again, {&xs[0], &xs[0]}, {&xs[0].mesh, &xs[0].mesh}), InvariantError);
}

TEST(PackPart, TheModelAndTheBlocksRoundTrip) {
  ModelInfo m;
  m.name = "t";
  m.source = "/x/t.msh";
  m.entities = {{0, 1, {}}, {2, 7, {-3, 4}}, {3, 1, {7}}};
  m.groups = {{3, 10, "bone", {1}}, {2, 11, "", {7}}};
  m.origin = ElementOrigin::kMeshFile;
  m.file_blocks = {{2, 7, 2}, {3, 1, 4}};
  m.high_order.order = 2;
  m.high_order.tags = {5};                        // not carried: a part has none
  m.periodic.push_back({2, 7, 8, {}, {1}, {2}});  // not carried: a part's nodes are pinned
  std::vector<ElementBlock> blocks = {{0, 1, 15, {101}, {0}, {}},
                                      {1, 3, 1, {5, 6}, {0, 1, 1, 2}, {9, 9}}};
  std::vector<char> buf;
  pack_model(m, buf);
  pack_blocks(blocks, buf);
  std::size_t pos = 0;
  ModelInfo back;
  std::vector<ElementBlock> bb;
  unpack_model(buf, pos, back);
  unpack_blocks(buf, pos, bb);
  EXPECT_EQ(pos, buf.size());
  EXPECT_EQ(back.name, m.name);
  EXPECT_EQ(back.source, m.source);
  ASSERT_EQ(back.entities.size(), 3u);
  EXPECT_EQ(back.entities[1].boundary, m.entities[1].boundary);
  ASSERT_EQ(back.groups.size(), 2u);
  EXPECT_EQ(back.groups[0].name, "bone");
  EXPECT_EQ(back.groups[1].entities, m.groups[1].entities);
  EXPECT_EQ(back.origin, ElementOrigin::kMeshFile);
  EXPECT_EQ(back.file_blocks, m.file_blocks);
  EXPECT_EQ(back.high_order.order, 2);
  EXPECT_TRUE(back.high_order.tags.empty());
  EXPECT_TRUE(back.periodic.empty());
  ASSERT_EQ(bb.size(), 2u);
  EXPECT_EQ(bb[1].gmsh_type, 1);
  EXPECT_EQ(bb[1].tags, blocks[1].tags);
  EXPECT_EQ(bb[1].nodes, blocks[1].nodes);
  EXPECT_EQ(bb[1].medit_refs, blocks[1].medit_refs);
  buf.resize(buf.size() - 3);
  pos = 0;
  unpack_model(buf, pos, back);
  EXPECT_THROW(unpack_blocks(buf, pos, bb), InvariantError);
}

TEST(PackPart, RoundTripAndShortBufferRefused) {
  const TetMesh m = testing::cube_sphere(0.2, 0.15).tet;
  std::vector<char> buf;
  pack_part(m, buf);
  pack_part(m, buf);
  TetMesh a, b;
  std::size_t pos = 0;
  unpack_part(buf, pos, a);
  unpack_part(buf, pos, b);
  EXPECT_EQ(pos, buf.size());
  for (const TetMesh* x : {&a, &b}) {
    EXPECT_EQ(x->xyz, m.xyz);
    EXPECT_EQ(x->tets, m.tets);
    EXPECT_EQ(x->tris, m.tris);
    EXPECT_EQ(x->tri_surface, m.tri_surface);
    EXPECT_EQ(x->node_tags, m.node_tags);
  }
  buf.resize(buf.size() - 5);
  pos = 0;
  TetMesh c;
  unpack_part(buf, pos, c);
  EXPECT_THROW(unpack_part(buf, pos, c), InvariantError);
}

}  // namespace
}  // namespace cvtmesh
