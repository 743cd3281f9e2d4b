#include "core/distributed/optimize_partitioned.h"

#include <chrono>
#include <cstring>
#include <string>

#include "core/distributed/partition_tets.h"
#include "core/mesh/bounding_box.h"
#include "core/mesh/build_adjacency.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/extract_regions.h"
#include "core/mesh/merge_regions.h"
#include "core/quality/worse_than.h"
#include "core/util/error.h"

namespace cvtmesh {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void check_merged(const TetMesh& mesh, int round) {
  const MeshCheck c = check_mesh(mesh);
  if (c.ok) return;
  throw InvariantError("optimize_partitioned: round " + std::to_string(round + 1) +
                       " left an invalid mesh: " + c.problems.front());
}

}  // namespace

PartitionedResult optimize_partitioned(TetMesh& mesh, const OptimizeOptions& options,
                                       const PartitionOptions& po, PartExchange& ex) {
  const auto t0 = std::chrono::steady_clock::now();
  if (po.parts < 1) throw InputError("partitioned optimization: parts must be at least 1");
  if (po.rounds < 1) throw InputError("partitioned optimization: rounds must be at least 1");
  if (!options.regions.empty() || !options.physical.empty())
    throw InputError(
        "partitioned optimization: a selection of volumes (regions, physical) "
        "does not apply; the whole mesh is partitioned");
  const bool root = ex.rank() == 0;
  PartitionedResult r;
  // Rank 0's header for every rank: the model the parts share and the bounding box's diagonal.
  std::vector<char> header;
  if (root) {
    if (mesh.adj.size() != 4 * static_cast<std::size_t>(mesh.nb_tets())) build_adjacency(mesh);
    r.before = quality_stats(mesh, "input");
    pack_model(mesh.model, header);
    const double diag = bounding_box_diagonal(mesh);
    const char* d = reinterpret_cast<const char*>(&diag);
    header.insert(header.end(), d, d + sizeof diag);
  }
  header = ex.broadcast(header);
  ModelInfo base;
  std::size_t hpos = 0;
  unpack_model(header, hpos, base);
  double diag = 0;
  if (header.size() != hpos + sizeof diag)
    throw InvariantError("optimize_partitioned: rank 0's header did not arrive");
  std::memcpy(&diag, header.data() + hpos, sizeof diag);
  // Rank 0 keeps the input (never worse) and counts the frozen vertices.
  const TetMesh input = root ? mesh : TetMesh{};
  const int nv0 = mesh.nb_vertices();
  std::vector<int> frozen_rounds(root ? nv0 : 0, 0);
  std::vector<char> previous_interface;
  OptimizeOptions so = options;
  so.progress = nullptr;
  // A part's quality is not the mesh's: whether to refine the interior is no part's decision
  // (an explicit refine_interior still applies in every part).
  so.auto_refine = false;
  const bool free = !options.fix_boundary;
  if (free) {
    // The free boundary in each part, on the part's own triangles (the discrete geometry: the
    // interface's edges, both ends pinned, are then never flipped), no surface coarsening (a
    // vertex removed from a part would leave the others' numbering). Each round may move the
    // surface by its share of the bounds: the distance to the input's boundary adds up over the
    // rounds (triangle inequality), so the whole run stays within the user's bound; the same for
    // the volume.
    so.boundary_model = nullptr;
    so.coarsen_surface = 0;
    so.hausdorff = (options.hausdorff > 0 ? options.hausdorff : 2e-3 * diag) / po.rounds;
    so.volume_tolerance = options.volume_tolerance / po.rounds;
  }
  for (int round = 0; round < po.rounds; ++round) {
    const auto tr = std::chrono::steady_clock::now();
    PartitionRound pr;
    // Rank 0 cuts (METIS keeps global state: it is not reentrant), extracts every part (the
    // merge needs them) and sends each rank its parts: part p to rank p mod size.
    std::vector<RegionSubmesh> xs;
    std::vector<std::vector<char>> to_ranks;
    if (root) {
      const TetPartition tp = partition_tets(mesh, po.parts, previous_interface);
      pr.nb_cut_faces = tp.nb_cut_faces;
      pr.nb_avoided_cut = tp.nb_avoided_cut;
      xs.resize(po.parts);
      pr.part_tets.assign(po.parts, 0);
      to_ranks.assign(ex.size(), {});
      for (int p = 0; p < po.parts; ++p) {
        std::vector<char> sel(mesh.nb_tets(), 0);
        for (int t = 0; t < mesh.nb_tets(); ++t) sel[t] = tp.part[t] == p;
        xs[p] = extract_tets(mesh, sel);
        pr.part_tets[p] = xs[p].mesh.nb_tets();
        pack_part(xs[p].mesh, to_ranks[p % ex.size()]);
        pack_blocks(xs[p].mesh.model.extra, to_ranks[p % ex.size()]);
      }
    }
    const std::vector<char> got = ex.scatter(to_ranks);
    to_ranks.clear();
    // This rank's parts, optimized and packed.
    std::vector<char> mine;
    std::size_t pos = 0;
    for (int p = ex.rank(); p < po.parts; p += ex.size()) {
      MeshData sub;
      sub.dim = 3;
      sub.tet.model = base;
      unpack_part(got, pos, sub.tet);
      unpack_blocks(got, pos, sub.tet.model.extra);
      build_adjacency(sub.tet);
      optimize(sub, so);
      pack_part(sub.tet, mine);
    }
    if (pos != got.size())
      throw InvariantError("optimize_partitioned: rank " + std::to_string(ex.rank()) +
                           " got more than its parts");
    const std::vector<std::vector<char>> all = ex.gather(mine);
    if (root) {
      if (static_cast<int>(all.size()) != ex.size())
        throw InvariantError("optimize_partitioned: a rank's parts did not arrive");
      std::vector<TetMesh> results(po.parts);
      for (int k = 0; k < ex.size(); ++k) {
        std::size_t at = 0;
        for (int p = k; p < po.parts; p += ex.size()) {
          results[p].model = xs[p].mesh.model;
          unpack_part(all[k], at, results[p]);
        }
        if (at != all[k].size())
          throw InvariantError("optimize_partitioned: rank " + std::to_string(k) +
                               " sent more than its parts");
      }
      // Which vertices were pinned as interface (between parts, not on the model's boundary).
      std::vector<char> interface(mesh.nb_vertices(), 0);
      for (const RegionSubmesh& x : xs)
        for (int i = 0; i < x.mesh.nb_vertices(); ++i)
          if (x.mesh.vclass[i].entity < 0 && mesh.vclass[x.to_parent[i]].entity >= 0 &&
              !interface[x.to_parent[i]]) {
            interface[x.to_parent[i]] = 1;
            ++pr.nb_interface;
          }
      for (int v = 0; v < nv0; ++v)
        if (interface[v] && input.vclass[v].dim == 3) ++frozen_rounds[v];
      std::vector<const RegionSubmesh*> xp;
      std::vector<const TetMesh*> rp;
      for (int p = 0; p < po.parts; ++p) {
        xp.push_back(&xs[p]);
        rp.push_back(&results[p]);
      }
      merge_parts(mesh, xp, rp, free);
      check_merged(mesh, round);
      previous_interface = std::move(interface);
      previous_interface.resize(mesh.nb_vertices(), 0);  // the parts' new vertices: not frozen
      pr.after = quality_stats(mesh, "round " + std::to_string(round + 1));
    }
    pr.seconds = seconds_since(tr);
    r.rounds.push_back(std::move(pr));
  }
  if (root) {
    for (int v = 0; v < nv0; ++v)
      if (frozen_rounds[v] == po.rounds) ++r.nb_frozen_every_round;
    r.after = quality_stats(mesh, "partitioned");
    if (options.never_worse) {
      const std::string worse = worse_than(r.after, r.before);
      if (!worse.empty()) {
        r.notes.push_back("the partitioned result was worse than the input (" + worse +
                          "): the input is kept unchanged");
        mesh = input;
        r.kept_input = true;
        r.after = r.before;
      }
    }
  }
  r.seconds = seconds_since(t0);
  return r;
}

}  // namespace cvtmesh
