#include "core/io/gmsh_repartition.h"

#include <gmsh.h>

#include <algorithm>
#include <filesystem>

#include "core/io/gmsh_session.h"

namespace cvtmesh {

std::uint64_t partition_fingerprint(const MeshData& data) {
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&](const void* p, std::size_t n) {
    const unsigned char* c = static_cast<const unsigned char*>(p);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ c[i]) * 1099511628211ULL;
  };
  auto add = [&](const auto& v) {
    const std::uint64_t n = v.size();
    mix(&n, sizeof n);
    if (!v.empty()) mix(v.data(), v.size() * sizeof(v[0]));
  };
  if (data.dim == 3) {
    add(data.tet.xyz);
    add(data.tet.tets);
    add(data.tet.tet_tags);
  } else {
    add(data.tri.xy);
    add(data.tri.tris);
    add(data.tri.tri_tags);
  }
  return h;
}

std::string file_stamp(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) return "";
  const auto time = std::filesystem::last_write_time(path, ec);
  if (ec) return "";
  return std::to_string(size) + ":" + std::to_string(time.time_since_epoch().count());
}

Repartitioned repartition_gmsh_model(const Partitioning& p, int dim) {
  Repartitioned r;
  if (p.nb_parts < 1) return r;
  gmsh_checked("cannot partition the mesh into " + std::to_string(p.nb_parts) + " parts", [&] {
    gmsh::option::setNumber("Mesh.PartitionCreateTopology", p.topology ? 1 : 0);
    gmsh::option::setNumber("Mesh.PartitionCreateGhostCells", p.ghost_cells ? 1 : 0);
    gmsh::option::setNumber("Mesh.PartitionSplitMeshFiles", 0);
    gmsh::model::mesh::partition(p.nb_parts);
    r.nb_parts = p.nb_parts;
    // The parts of the cells, against the input's.
    if (p.cell_tags.empty()) return;
    std::size_t matched = 0;
    bool same = true;
    gmsh::vectorpair ents;
    gmsh::model::getEntities(ents, dim);
    for (const auto& [d, t] : ents) {
      std::string type;
      gmsh::model::getType(d, t, type);
      if (type.rfind("Partition", 0) != 0) continue;
      std::vector<int> parts;
      gmsh::model::getPartitions(d, t, parts);
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> tags, nodes;
      gmsh::model::mesh::getElements(types, tags, nodes, d, t);
      for (const auto& block : tags)
        for (std::size_t tag : block) {
          const auto it = std::lower_bound(p.cell_tags.begin(), p.cell_tags.end(), tag);
          same = same && parts.size() == 1 && it != p.cell_tags.end() && *it == tag &&
                 p.cell_parts[it - p.cell_tags.begin()] == parts[0];
          ++matched;
        }
    }
    r.same_as_input = same && matched == p.cell_tags.size();
  });
  return r;
}

std::string repartition_note(const Partitioning& p, const Repartitioned& r,
                             const std::string& path) {
  const std::string n = std::to_string(p.nb_parts);
  if (r.unreadable_msh22)
    return "'" + path + "' holds the mesh unpartitioned: Gmsh 4.8 could not read back the " +
           "partitioned MSH 2.2 file it wrote (\"No mesh elements were found\"); write MSH 4.1 " +
           "(--msh-version 4.1) to keep the " + n + " parts";
  if (r.nb_parts == 0)
    return "the input was partitioned into " + n + " parts; '" + path +
           "' holds the mesh unpartitioned (only a .msh holds partitions)";
  const std::string ghosts = p.ghost_cells ? ", with ghost cells" : "";
  if (r.kept_input_file)
    return "'" + path + "' holds the input's " + n + " parts as they were" + ghosts +
           " (its mesh unchanged)";
  if (r.same_as_input)
    return "'" + path + "' partitioned into " + n + " parts by Gmsh (METIS)" + ghosts +
           ": the input's element-to-part assignment";
  return "'" + path + "' partitioned again into " + n + " parts by Gmsh (METIS)" + ghosts +
         ": the element-to-part assignment is not the input's (METIS cut this mesh anew)";
}

}  // namespace cvtmesh
