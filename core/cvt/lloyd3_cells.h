// The restricted Voronoi cells of one configuration of the 3D Lloyd iteration (lloyd3.h): every
// vertex's cell clipped to its region, under rho = 1/H^5 interpolated (P1) from the vertices.
#pragma once
#include <vector>

#include "core/cvt/cell_mesh.h"
#include "core/cvt/lloyd.h"
#include "core/cvt/sizing_field3.h"
#include "core/cvt/voronoi_cell3.h"
#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

// The CVT energy F = sum_i int_{V_i ∩ region} rho |x - z_i|^2 of the current mesh (all vertices),
// and the centroid of every vertex's restricted cell (3 per vertex). Exposed for tests.
struct CellCentroids {
  std::vector<double> centroid;  // 3 * #V (fixed vertices included)
  std::vector<double> mass;      // #V
  double energy = 0;
};

// What one evaluation gives the moves: the free vertices (vclass dim 3, with tets) in vertex
// order, their positions z and cell centroids c (3 per free vertex; c = z where the cell is empty
// or degenerate, then mass 0) and cell masses (1 per free vertex); F over the evaluated cells.
struct Lloyd3Cells {
  double energy = 0;
  std::vector<int> free_ids;
  std::vector<double> z, c, mass;
};

// Buffers kept from one iteration to the next. After lloyd3_cells, `cm` is the cell mesh of the
// evaluated configuration (its stars and constrained faces serve the move safeguard).
struct Lloyd3CellBuffers {
  CellMesh cm;
  std::vector<int> hints;            // #V: where the sizing field found each vertex last time
  std::vector<double> H, rho;        // #V: size and density at the vertices
  std::vector<CellIntegrals> cells;  // #V: the cells of the last evaluation (lloyd3_cells)
};

CellCentroids voronoi_centroids_3d(const TetMesh& mesh, const SizingField3& sizing,
                                   std::vector<int>* sizing_hints = nullptr);
// The same, with the buffers kept from one call to the next (the constrained CVT calls it once per
// round: at 1M tets the cell mesh's dual pieces are ~200 MB, allocated and paged in each time
// otherwise). Identical results.
CellCentroids voronoi_centroids_3d(const TetMesh& mesh, const SizingField3& sizing,
                                   Lloyd3CellBuffers& buffers);

// The cells of every free vertex (and of the fixed ones if compute_energy: the full F), computed
// in parallel and reduced in vertex order (the result does not depend on the number of threads).
// `delaunay_known`: every unconstrained face of `mesh` is locally Delaunay, except perhaps those in
// `non_delaunay` if given (prepare_cell_mesh).
// Fills s.energy, s.nb_free, s.D (the paper's D: the full move to the centroid, relative to H) and
// the counts of dual and clipped cells.
Lloyd3Cells lloyd3_cells(const TetMesh& mesh, const SizingField3& sizing, bool compute_energy,
                         bool delaunay_known, Lloyd3CellBuffers& buffers, LloydStep& s,
                         const std::vector<FaceKey>* non_delaunay = nullptr);

// xyz (3*#V) with the free vertices `free_ids` moved to `free_xyz` (3 per free vertex).
std::vector<double> with_free_positions(const std::vector<double>& xyz,
                                        const std::vector<int>& free_ids,
                                        const std::vector<double>& free_xyz);

}  // namespace cvtmesh
