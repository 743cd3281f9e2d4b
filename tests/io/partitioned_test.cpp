// Partitioned Gmsh meshes (gmsh -part N, -part_ghosts, t21): read as their model (the partition
// entities' mesh on their parents, ghost cells and the interfaces between parts skipped), they
// optimize as the same mesh unpartitioned does, and a .msh output is partitioned again into as
// many parts, with ghost cells iff the input had them and the model's physical groups; an
// unchanged mesh (convert) keeps its own parts; one file of a split mesh is refused.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/io/read_mesh.h"
#include "core/mesh/check_mesh.h"
#include "core/util/error.h"
#include "plugin/gmsh_inprocess.h"
#include "tests/support/test_meshes.h"

namespace cvtmesh {
namespace {

using testing::run;

// A t5-like OCC model: a box with two balls (volumes 2, 3 the balls, 4 the box), the volumes in
// physical groups and one ball's surface too (its triangles are in the file).
const char* kBoxBalls =
    "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 1, 1, 1};\n"
    "Sphere(2) = {0.3, 0.5, 0.5, 0.2};\nSphere(3) = {0.72, 0.5, 0.5, 0.18};\n"
    "BooleanFragments{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; }\n"
    "Physical Volume(\"balls\", 1) = {2, 3};\nPhysical Volume(\"box\", 10) = {4};\n"
    "Physical Surface(\"skin\", 5) = {Boundary{ Volume{2}; }};\nMesh.MeshSizeMax = 0.1;\n";

// t21's model: two squares sharing an edge, one physical group each.
const char* kTwoSquares =
    "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 1, 1};\n"
    "Rectangle(2) = {1, 0, 0, 1, 1};\n"
    "BooleanFragments{ Surface{1}; Delete; }{ Surface{2}; Delete; }\nMeshSize {:} = 0.08;\n"
    "Physical Surface(\"Left\", 100) = 1;\nPhysical Surface(\"Right\", 200) = 2;\n";

// The model meshed by the gmsh executable with `flags` (e.g. "-3 -part 3").
std::string gmsh_file(const std::string& dir, const char* geo_text, const std::string& flags,
                      const std::string& name) {
  const std::string geo = dir + "/model.geo";
  std::ofstream(geo) << geo_text;
  const std::string path = dir + "/" + name;
  std::string log;
  EXPECT_EQ(run("gmsh -v 0 " + flags + " " + geo + " -o " + path, &log), 0) << log;
  return path;
}

// What Gmsh itself sees of a file's partitions.
struct PartsSeen {
  int nb_parts = 0;  // the largest part number of an entity
  int partition_entities = 0, ghost_entities = 0;
  // The groups of the cells' dimension: (tag, name).
  std::set<std::pair<int, std::string>> cell_groups;
  // The cells (sorted node tags) of the partition entities and their parts.
  std::map<std::vector<std::size_t>, int> cell_part;
};

PartsSeen parts_seen(const std::string& path, int dim) {
  GmshSession session;
  PartsSeen s;
  gmsh::open(path);
  gmsh::vectorpair ents;
  gmsh::model::getEntities(ents);
  for (const auto& [d, t] : ents) {
    std::string type;
    gmsh::model::getType(d, t, type);
    const bool ghost = type.rfind("Ghost", 0) == 0, part = type.rfind("Partition", 0) == 0;
    s.ghost_entities += ghost;
    s.partition_entities += part;
    std::vector<int> parts;
    gmsh::model::getPartitions(d, t, parts);
    for (int p : parts) s.nb_parts = std::max(s.nb_parts, p);
    if (!part || d != dim || parts.size() != 1) continue;
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, d, t);
    for (std::size_t k = 0; k < types.size(); ++k) {
      const std::size_t n = nodes[k].size() / tags[k].size();
      for (std::size_t e = 0; e < tags[k].size(); ++e) {
        std::vector<std::size_t> cell(&nodes[k][n * e], &nodes[k][n * e] + n);
        std::sort(cell.begin(), cell.end());
        s.cell_part[cell] = parts[0];
      }
    }
  }
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim);
  for (const auto& [d, t] : groups) {
    std::string name;
    gmsh::model::getPhysicalName(d, t, name);
    s.cell_groups.insert({t, name});
  }
  gmsh::model::remove();
  return s;
}

using Group = std::tuple<int, int, std::string, std::vector<int>>;
std::vector<Group> groups_of(const MeshData& d) {
  std::vector<Group> out;
  for (const auto& g : d.model().groups) out.emplace_back(g.dim, g.tag, g.name, g.entities);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::pair<int, int>> entities_of(const MeshData& d) {
  std::vector<std::pair<int, int>> out;
  for (const auto& e : d.model().entities) out.emplace_back(e.dim, e.tag);
  std::sort(out.begin(), out.end());
  return out;
}

// Facets (sorted vertex ids) between two cells of one region: the interfaces between parts, which
// must not come back as constrained facets.
int facets_inside_a_region(const TetMesh& m) {
  std::map<std::vector<int>, std::vector<int>> regions;  // face -> regions of its tets
  static const int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
  for (int t = 0; t < m.nb_tets(); ++t)
    for (const auto& f : kFace) {
      std::vector<int> key = {m.tets[4 * t + f[0]], m.tets[4 * t + f[1]], m.tets[4 * t + f[2]]};
      std::sort(key.begin(), key.end());
      regions[key].push_back(m.tet_region[t]);
    }
  int inside = 0;
  for (int f = 0; f < m.nb_tris(); ++f) {
    std::vector<int> key(&m.tris[3 * f], &m.tris[3 * f] + 3);
    std::sort(key.begin(), key.end());
    const auto& r = regions[key];
    inside += r.size() == 2 && r[0] == r[1];
  }
  return inside;
}

// The optimize run's report ("after": the quality row of the output) and its stderr.
nlohmann::json optimize(const std::string& in, const std::string& out, std::string* log) {
  const std::string report = out + ".json";
  EXPECT_EQ(
      run(testing::cli_path() + " optimize " + in + " -o " + out + " --report " + report, log), 0)
      << *log;
  std::ifstream f(report);
  return nlohmann::json::parse(f);
}

// The rows of the quality table that an optimization must reproduce from the same mesh.
// Equal, not close: both inputs are read as the same mesh in the same order, and the
// optimization is deterministic.
void expect_same_rows(const nlohmann::json& a, const nlohmann::json& b) {
  for (const char* key :
       {"number_of_elements", "q_0.7_1.0", "q_0.5_0.7", "q_0.3_0.5", "q_0.0_0.3", "q_min",
        "average_quality", "min_angle", "max_angle", "average_radius_ratio", "time_step"})
    EXPECT_EQ(a[key], b[key]) << key;
}

std::vector<int> class_dims(const std::vector<VertexClass>& vclass) {
  std::vector<int> n(4, 0);
  for (const auto& c : vclass) ++n[c.dim];
  return n;
}

TEST(Partitioned, ReadAsTheUnpartitionedModel3D) {
  const std::string dir = testing::temp_dir();
  const std::string whole = gmsh_file(dir, kBoxBalls, "-3", "whole.msh");
  const MeshData w = read_mesh(whole);
  ASSERT_EQ(w.dim, 3);
  EXPECT_EQ(w.model().partitioning.nb_parts, 0);
  for (const auto& [flags, parts, ghosts] :
       {std::tuple<std::string, int, bool>{"-part 3", 3, false},
        std::tuple<std::string, int, bool>{"-part 2 -part_ghosts", 2, true}}) {
    SCOPED_TRACE(flags);
    const std::string path = gmsh_file(dir, kBoxBalls, "-3 " + flags, "parts.msh");
    const PartsSeen seen = parts_seen(path, 3);
    ASSERT_EQ(seen.nb_parts, parts) << "the file under test is not partitioned";
    ASSERT_EQ(seen.ghost_entities > 0, ghosts);
    const MeshData d = read_mesh(path);
    ASSERT_EQ(d.dim, 3);
    EXPECT_TRUE(check_mesh(d.tet).ok);
    // The regions are the model volumes, not the partition entities.
    EXPECT_EQ(std::set<int>(d.tet.tet_region.begin(), d.tet.tet_region.end()),
              (std::set<int>{2, 3, 4}));
    EXPECT_EQ(facets_inside_a_region(d.tet), 0);
    // The same mesh as the unpartitioned file, in the same order: coordinates, cells, facets
    // (restored the same way), classification, entities and groups.
    EXPECT_EQ(d.tet.xyz, w.tet.xyz);
    EXPECT_EQ(d.tet.tets, w.tet.tets);
    EXPECT_EQ(d.tet.tet_region, w.tet.tet_region);
    EXPECT_EQ(d.tet.tris, w.tet.tris);
    EXPECT_EQ(d.tet.tri_surface, w.tet.tri_surface);
    EXPECT_EQ(class_dims(d.tet.vclass), class_dims(w.tet.vclass));
    EXPECT_EQ(entities_of(d), entities_of(w));
    EXPECT_EQ(groups_of(d), groups_of(w));
    EXPECT_EQ(d.model().file_blocks, w.model().file_blocks);
    const Partitioning& p = d.model().partitioning;
    EXPECT_EQ(p.nb_parts, parts);
    EXPECT_EQ(p.ghost_cells, ghosts);
    EXPECT_TRUE(p.topology);
    EXPECT_EQ(p.cell_tags.size(), static_cast<std::size_t>(d.tet.nb_tets()));
  }
}

TEST(Partitioned, OptimizedOutputIsPartitionedAgain3D) {
  const std::string dir = testing::temp_dir();
  const std::string whole = gmsh_file(dir, kBoxBalls, "-3", "whole.msh");
  std::string log;
  const nlohmann::json ref = optimize(whole, dir + "/whole_out.msh", &log)["after"];
  const MeshData ref_out = read_mesh(dir + "/whole_out.msh");
  EXPECT_EQ(parts_seen(dir + "/whole_out.msh", 3).partition_entities, 0);
  for (const auto& [flags, parts, ghosts] :
       {std::tuple<std::string, int, bool>{"-part 3", 3, false},
        std::tuple<std::string, int, bool>{"-part 2 -part_ghosts", 2, true}}) {
    SCOPED_TRACE(flags);
    const std::string in = gmsh_file(dir, kBoxBalls, "-3 " + flags, "parts.msh");
    const std::string out = dir + "/parts_out.msh";
    const nlohmann::json r = optimize(in, out, &log);
    EXPECT_NE(
        log.find("partitioned again into " + std::to_string(parts) + " parts by Gmsh (METIS)"),
        std::string::npos)
        << log;
    std::string check;
    EXPECT_EQ(run(testing::cli_path() + " check " + out, &check), 0) << check;
    // Optimized as the unpartitioned mesh is (the same mesh in the same order).
    expect_same_rows(r["after"], ref);
    // Gmsh reads the output as partitioned into as many parts, ghost cells iff the input had
    // them, the cells' physical groups those of the input.
    const PartsSeen in_seen = parts_seen(in, 3), out_seen = parts_seen(out, 3);
    EXPECT_EQ(out_seen.nb_parts, parts);
    EXPECT_GT(out_seen.partition_entities, 0);
    EXPECT_EQ(out_seen.ghost_entities > 0, ghosts);
    EXPECT_EQ(out_seen.cell_groups, in_seen.cell_groups);
    // Read back: the model's groups, and its nodes on their curves and points as in the
    // unpartitioned output (the partitioner keeps them there: add_curve_point_elements).
    const MeshData back = read_mesh(out), in_read = read_mesh(in);
    EXPECT_TRUE(check_mesh(back.tet).ok);
    EXPECT_EQ(groups_of(back), groups_of(in_read));
    EXPECT_EQ(back.model().partitioning.nb_parts, parts);
    EXPECT_EQ(class_dims(back.tet.vclass), class_dims(ref_out.tet.vclass));
  }
}

TEST(Partitioned, TwoSquaresLikeT21) {
  const std::string dir = testing::temp_dir();
  const std::string whole = gmsh_file(dir, kTwoSquares, "-2", "whole.msh");
  const std::string in = gmsh_file(dir, kTwoSquares, "-2 -part 3", "parts.msh");
  ASSERT_EQ(parts_seen(in, 2).nb_parts, 3);
  const MeshData w = read_mesh(whole), d = read_mesh(in);
  ASSERT_EQ(d.dim, 2);
  EXPECT_TRUE(check_mesh(d.tri).ok);
  EXPECT_EQ(std::set<int>(d.tri.tri_region.begin(), d.tri.tri_region.end()), (std::set<int>{1, 2}));
  // No lines on the interfaces between parts: the lines are the unpartitioned file's.
  EXPECT_EQ(d.tri.xy, w.tri.xy);
  EXPECT_EQ(d.tri.tris, w.tri.tris);
  EXPECT_EQ(d.tri.edges, w.tri.edges);
  EXPECT_EQ(d.tri.edge_curve, w.tri.edge_curve);
  EXPECT_EQ(groups_of(d), groups_of(w));
  EXPECT_EQ(d.model().partitioning.nb_parts, 3);

  std::string log;
  const nlohmann::json ref = optimize(whole, dir + "/whole_out.msh", &log)["after"];
  const nlohmann::json r = optimize(in, dir + "/parts_out.msh", &log);
  expect_same_rows(r["after"], ref);
  std::string check;
  EXPECT_EQ(run(testing::cli_path() + " check " + dir + "/parts_out.msh", &check), 0) << check;
  const PartsSeen out_seen = parts_seen(dir + "/parts_out.msh", 2);
  EXPECT_EQ(out_seen.nb_parts, 3);
  EXPECT_EQ(out_seen.ghost_entities, 0);
  EXPECT_EQ(out_seen.cell_groups, parts_seen(in, 2).cell_groups);
  const MeshData back = read_mesh(dir + "/parts_out.msh");
  EXPECT_EQ(groups_of(back), groups_of(d));
  // The nodes on their curves and points as in the unpartitioned output.
  EXPECT_EQ(class_dims(back.tri.vclass), class_dims(read_mesh(dir + "/whole_out.msh").tri.vclass));
}

TEST(Partitioned, ConvertKeepsTheInputsParts) {
  const std::string dir = testing::temp_dir();
  const std::string in = gmsh_file(dir, kBoxBalls, "-3 -part 3", "parts.msh");
  std::string log;
  ASSERT_EQ(run(testing::cli_path() + " convert " + in + " " + dir + "/c.msh", &log), 0) << log;
  EXPECT_NE(log.find("holds the input's 3 parts as they were"), std::string::npos) << log;
  const PartsSeen a = parts_seen(in, 3), b = parts_seen(dir + "/c.msh", 3);
  ASSERT_EQ(a.cell_part.size(), static_cast<std::size_t>(read_mesh(in).tet.nb_tets()));
  EXPECT_EQ(b.cell_part, a.cell_part);
  EXPECT_EQ(b.nb_parts, 3);
  // Our own writers hold no partitions: the mesh unpartitioned, said so.
  ASSERT_EQ(run(testing::cli_path() + " convert " + in + " " + dir + "/c.vtk", &log), 0) << log;
  EXPECT_NE(log.find("holds the mesh unpartitioned"), std::string::npos) << log;
  EXPECT_EQ(read_mesh(dir + "/c.vtk").tet.nb_tets(), read_mesh(in).tet.nb_tets());
}

TEST(Partitioned, SplitFileAndPartitionedSurfaceMeshAreRefused) {
  const std::string dir = testing::temp_dir();
  gmsh_file(dir, kBoxBalls, "-3 -part 3 -part_split", "split.msh");
  const std::string part = dir + "/split_2.msh";
  try {
    read_mesh(part);
    FAIL() << "one part of a split mesh was read as a mesh";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'" + part + "' holds part 2 of 3"), std::string::npos) << m;
    EXPECT_NE(m.find("-part_split"), std::string::npos) << m;
  }
  // A partitioned surface mesh without tetrahedra: Gmsh meshes a volume from its model
  // surfaces' elements, which the partition entities hold.
  const std::string surface = gmsh_file(dir, kBoxBalls, "-2 -save_all -part 3", "surface.msh");
  try {
    read_mesh(surface);
    FAIL() << "a partitioned surface mesh had its volumes meshed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("partitioned surface mesh"), std::string::npos)
        << e.what();
  }
}

// A Gmsh session owned by the test, as a script's would be.
class PartitionedInProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    gmsh::initialize(0, nullptr, false);
    gmsh::option::setNumber("General.Terminal", 0);
    set_gmsh_initialized_by_caller(true);
  }
  void TearDown() override {
    gmsh::finalize();
    set_gmsh_initialized_by_caller(false);
  }
};

TEST_F(PartitionedInProcess, ModelStaysPartitioned) {
  const std::string dir = testing::temp_dir();
  const std::string in = gmsh_file(dir, kBoxBalls, "-3 -part 3", "parts.msh");
  gmsh::open(in);
  GmshOptimizeOptions o;
  o.optimize.fix_boundary = true;
  o.optimize.max_iterations = 3;
  const GmshOptimizeResult r = gmsh_optimize(o);
  int parts = 0, partition_volumes = 0;
  gmsh::vectorpair ents;
  gmsh::model::getEntities(ents, 3);
  for (const auto& [d, t] : ents) {
    std::string type;
    gmsh::model::getType(d, t, type);
    if (type.rfind("Partition", 0) != 0) continue;
    ++partition_volumes;
    std::vector<int> p;
    gmsh::model::getPartitions(d, t, p);
    for (int x : p) parts = std::max(parts, x);
  }
  EXPECT_EQ(parts, 3);
  EXPECT_GT(partition_volumes, 0);
  const MeshData now = mesh_from_gmsh(3);
  EXPECT_TRUE(check_mesh(now.tet).ok);
  EXPECT_EQ(now.tet.nb_tets(), r.result.after.nb_elements);
  EXPECT_EQ(std::set<int>(now.tet.tet_region.begin(), now.tet.tet_region.end()),
            (std::set<int>{2, 3, 4}));
}

}  // namespace
}  // namespace cvtmesh
