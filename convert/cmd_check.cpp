// cvtmesh check IN: validity of a mesh (orientation, adjacency, closed boundary, interfaces).
#include <iostream>
#include <memory>

#include "convert/cli_common.h"
#include "core/io/place_mid_edge_nodes.h"
#include "core/mesh/check_mesh.h"
#include "core/mesh/find_coincident_vertices.h"
#include "core/mesh/check_quads2d.h"
#include "core/mesh/check_surface_mesh.h"
#include "core/pipeline/find_structural_defects.h"
#include "core/pipeline/volumes_apart.h"

namespace cvtmesh::cli {

// A vertex's node tag in the file (its 0-based id + 1 when the file gave none).
static std::size_t node_label(const TriMesh2& m, int v) {
  return v < static_cast<int>(m.node_tags.size()) && m.node_tags[v]
             ? m.node_tags[v]
             : static_cast<std::size_t>(v) + 1;
}

void register_check(CLI::App& app) {
  auto in = std::make_shared<InputOpts>();
  CLI::App* c = app.add_subcommand("check",
                                   "check a mesh: positive orientation, symmetric adjacency, "
                                   "closed boundary, interfaces present");
  add_input(c, *in);
  commands().push_back(
      {c, [in] {
         // read_mesh already refuses flat elements, tangled and open meshes with a clear
         // message; what reaches here is checked again in full.
         const MeshData d = read_mesh(in->path, in->to_read_options());
         MeshCheck r = d.dim == 3 ? check_mesh(d.tet) : check_mesh(d.tri);
         // Tets the file gives with negative volume: read (turned positive) by every command,
         // but the file is not valid as it is.
         if (d.model().nb_reoriented > 0) {
           r.ok = false;
           r.problems.push_back(
               std::to_string(d.model().nb_reoriented) +
               (d.dim == 3 ? " tetrahedra have negative volume (the other vertex order; "
                             "optimize and convert write them positive)"
                           : " triangles turn the other way round than their surface's majority "
                             "(mixed orientation; optimize and convert write them as the "
                             "surface's)"));
         }
         const long n = d.dim == 3 ? d.tet.nb_tets() : d.tri.nb_tris();
         // Structure: a self-intersecting boundary is invalid; coincident
         // nodes (parts in contact) are reported as a warning.
         // A surface mesh in space: its surfaces may cross one another (CAD faces that bound no
         // volume), a warning; a surface crossing itself or folded onto itself is invalid.
         const bool surface = d.dim == 3 && is_surface_mesh(d.tet);
         if (surface) {
           StructuralDefects s = find_structural_defects(d.tet);
           StructuralDefects across;
           auto& pairs = s.intersecting_tris;
           for (auto it = pairs.begin(); it != pairs.end();)
             if (d.tet.tri_surface[(*it)[0]] != d.tet.tri_surface[(*it)[1]]) {
               across.intersecting_tris.push_back(*it);
               it = pairs.erase(it);
             } else {
               ++it;
             }
           for (const auto& line : across.describe(d.tet))
             info() << in->path << ": warning: " << line << " (different surfaces)\n";
           const auto lines = s.describe(d.tet);
           for (std::size_t i = 0; i < lines.size(); ++i) {
             if (i == 0 && !s.intersecting_tris.empty()) {
               r.ok = false;
               r.problems.push_back(lines[i]);
             } else {
               info() << in->path << ": warning: " << lines[i] << "\n";
             }
           }
           const auto folds = folded_triangle_pairs(d.tet);
           if (!folds.empty()) {
             r.ok = false;
             const auto& f = folds.front();
             r.problems.push_back(std::to_string(folds.size()) +
                                  " pairs of neighbouring triangles of one surface are folded onto "
                                  "each other (first: triangles " +
                                  std::to_string(f[0]) + " and " + std::to_string(f[1]) +
                                  " of surface " + std::to_string(d.tet.tri_surface[f[0]]) + ")");
           }
         } else if (d.dim == 3) {
           const StructuralDefects s = find_structural_defects(d.tet);
           const auto lines = s.describe(d.tet);
           // Volumes that overlap or touch without a common mesh (an assembly meshed part by
           // part), each valid alone: a warning (optimize runs on each volume apart).
           const bool apart = !s.empty() && !volumes_defective_only_together(d.tet).empty();
           if (apart)
             info() << in->path << ": warning: the volumes overlap or touch without sharing "
                    << "their mesh (each volume alone is valid):\n";
           for (std::size_t i = 0; i < lines.size(); ++i) {
             const bool intersect = i == 0 && !s.intersecting_tris.empty() && !apart;
             if (intersect) {
               r.ok = false;
               r.problems.push_back(lines[i]);
             } else {
               info() << in->path << ": warning: " << lines[i] << "\n";
             }
           }
         }
         // A 2D hybrid mesh's quadrangles: each strictly convex in its surface's turning sense.
         QuadCheck quads;
         if (d.dim == 2) {
           // Coincident nodes (a crack's two lips, parts in contact): a warning.
           std::vector<double> xyz(3 * static_cast<std::size_t>(d.tri.nb_vertices()), 0.0);
           std::vector<char> used(d.tri.nb_vertices(), 0);
           for (int v = 0; v < d.tri.nb_vertices(); ++v) {
             xyz[3 * v] = d.tri.xy[2 * v];
             xyz[3 * v + 1] = d.tri.xy[2 * v + 1];
           }
           for (int v : d.tri.tris) used[v] = 1;
           const auto pairs = find_coincident_vertices(xyz, used, 1e-10);
           if (!pairs.empty())
             info() << in->path << ": warning: " << pairs.size()
                    << " pairs of nodes at the same place (a crack's lips, parts in contact; "
                    << "first: nodes " << node_label(d.tri, pairs[0][0]) << " and "
                    << node_label(d.tri, pairs[0][1]) << ")\n";
           quads = check_quads2d(d.tri);
           r.ok &= quads.ok();
           if (quads.nb_inverted)
             r.problems.push_back(std::to_string(quads.nb_inverted) +
                                  " quadrangles are inverted (they turn against their surface)");
           if (quads.nb_not_convex)
             r.problems.push_back(std::to_string(quads.nb_not_convex) +
                                  " quadrangles are not convex (a reflex or flat corner)");
           r.problems.insert(r.problems.end(), quads.problems.begin(), quads.problems.end());
         }
         // Order 2: every tet10 / tri6 positive as the file places its nodes.
         const bool order2 = d.model().high_order.order == 2;
         if (order2) {
           const MidEdgePlacement p = d.dim == 3 ? place_mid_edge_nodes(d.tet, {}, false)
                                                 : place_mid_edge_nodes(d.tri, {}, false);
           if (p.nb_invalid && d.dim == 3)
             r.problems.push_back(std::to_string(p.nb_invalid) +
                                  " order-2 tetrahedra are not positive with their mid-edge nodes "
                                  "(a straight sub-tet or the Jacobian at a node is not positive)");
           if (p.nb_invalid && d.dim == 2)
             r.problems.push_back(std::to_string(p.nb_invalid) +
                                  " order-2 triangles are not positive with their mid-edge nodes "
                                  "(a straight sub-triangle or the Jacobian somewhere on the "
                                  "triangle is not positive)");
           r.ok &= p.nb_invalid == 0;
         }
         if (r.ok) {
           std::cout << in->path << ": ok (" << (order2 ? "order 2, " : "")
                     << (surface ? d.tet.nb_tris() : n)
                     << (surface      ? " triangles of a surface mesh in space"
                         : d.dim == 3 ? " tetrahedra"
                                      : " triangles")
                     << (quads.nb_quads ? ", " + std::to_string(quads.nb_quads) + " quadrangles"
                                        : std::string())
                     << ", " << (d.dim == 3 ? d.tet.nb_vertices() : d.tri.nb_vertices())
                     << " vertices)\n";
           return 0;
         }
         std::cout << in->path << ": INVALID\n";
         for (const auto& p : r.problems) std::cout << "  " << p << "\n";
         return kExitCheckFailed;
       }});
}

}  // namespace cvtmesh::cli
