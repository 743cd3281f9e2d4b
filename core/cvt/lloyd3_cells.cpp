#include "core/cvt/lloyd3_cells.h"

#include <cmath>
#include <utility>

#include "core/cvt/voronoi_cell3.h"

namespace cvtmesh {
namespace {

// rho = 1/H^5 at every vertex of the mesh (P1 density for the cells); H at every vertex too.
void vertex_density(const TetMesh& m, const SizingField3& sizing, std::vector<int>& hints,
                    std::vector<double>& H, std::vector<double>& rho) {
  const int nv = m.nb_vertices();
  hints.resize(nv, -1);
  H.resize(nv);
  rho.resize(nv);
#pragma omp parallel for schedule(static, 512) if (sizing.thread_safe())
  for (int v = 0; v < nv; ++v) {
    double g[3];
    // No hint yet (first call): start from where the previous vertex of this chunk was found —
    // vertices are in space order, so the walk is short (same chunks for any thread count).
    if (hints[v] < 0 && v % 512 != 0) hints[v] = hints[v - 1];
    H[v] = sizing.eval(m.point(v), g, &hints[v]);
    rho[v] = 1.0 / std::pow(H[v], 5);
  }
}

}  // namespace

CellCentroids voronoi_centroids_3d(const TetMesh& mesh, const SizingField3& sizing,
                                   std::vector<int>* hints) {
  Lloyd3CellBuffers b;
  if (hints) b.hints = std::move(*hints);
  CellCentroids c = voronoi_centroids_3d(mesh, sizing, b);
  if (hints) *hints = std::move(b.hints);
  return c;
}

CellCentroids voronoi_centroids_3d(const TetMesh& mesh, const SizingField3& sizing,
                                   Lloyd3CellBuffers& b) {
  CellCentroids c;
  const int nv = mesh.nb_vertices();
  c.centroid.assign(3 * static_cast<std::size_t>(nv), 0);
  c.mass.assign(nv, 0);
  vertex_density(mesh, sizing, b.hints, b.H, b.rho);
  const std::vector<double>& rho = b.rho;
  prepare_cell_mesh(mesh, &rho, false, b.cm);
  const CellMesh& cm = b.cm;
  // The cells in parallel, summed in vertex order (the result does not depend on the number of
  // threads; the boundary CVT calls this once per round on the whole mesh).
  std::vector<double> energy(nv, 0);
#pragma omp parallel
  {
    CellWorkspace ws;
#pragma omp for schedule(dynamic, 64)
    for (int v = 0; v < nv; ++v) {
      const double* z = mesh.point(v);
      if (cm.star.nb_tets_of(v) == 0) {
        for (int d = 0; d < 3; ++d) c.centroid[3 * v + d] = z[d];
        continue;
      }
      CellIntegrals ci;
      if (!dual_voronoi_cell(mesh, cm, v, ci)) ci = restricted_voronoi_cell(mesh, cm, v, ws, &rho);
      const Vec3 x = ci.centroid(z);
      for (int d = 0; d < 3; ++d) c.centroid[3 * v + d] = x[d];
      c.mass[v] = ci.mass;
      energy[v] = ci.energy;
    }
  }
  for (int v = 0; v < nv; ++v) c.energy += energy[v];
  return c;
}

Lloyd3Cells lloyd3_cells(const TetMesh& m, const SizingField3& sizing, bool compute_energy,
                         bool delaunay_known, Lloyd3CellBuffers& b, LloydStep& s,
                         const std::vector<FaceKey>* non_delaunay) {
  const int nv = m.nb_vertices();
  vertex_density(m, sizing, b.hints, b.H, b.rho);
  prepare_cell_mesh(m, &b.rho, delaunay_known, b.cm, non_delaunay);
  const VertexStar& star = b.cm.star;
  // Written for every wanted vertex below, read only for those.
  std::vector<CellIntegrals>& cells = b.cells;
  cells.resize(nv);
  std::vector<char> wanted(nv, 0), clipped(nv, 1);
  for (int v = 0; v < nv; ++v) {
    const bool has_star = star.offset[v] < star.offset[v + 1];
    wanted[v] = has_star && (m.vclass[v].dim == 3 || compute_energy);
  }
#pragma omp parallel
  {
    CellWorkspace local_ws;
#pragma omp for schedule(dynamic, 64)
    for (int v = 0; v < nv; ++v) {
      if (!wanted[v]) continue;
      if (dual_voronoi_cell(m, b.cm, v, cells[v]))
        clipped[v] = 0;
      else
        cells[v] = restricted_voronoi_cell(m, b.cm, v, local_ws, &b.rho);
    }
  }
  for (int v = 0; v < nv; ++v)
    if (wanted[v]) (clipped[v] ? s.nb_clipped_cells : s.nb_dual_cells)++;
  Lloyd3Cells e;
  e.free_ids.reserve(nv);
  e.z.reserve(3 * static_cast<std::size_t>(nv));
  e.c.reserve(3 * static_cast<std::size_t>(nv));
  e.mass.reserve(nv);
  double dsum = 0;
  for (int v = 0; v < nv; ++v) {
    if (!wanted[v]) continue;
    const CellIntegrals& ci = cells[v];
    s.energy += ci.energy;
    if (m.vclass[v].dim != 3) continue;
    const double* z = m.point(v);
    ++s.nb_free;
    Vec3 c = ci.centroid(z);
    double mass = ci.mass;
    if (!(mass > 0) || !std::isfinite(c[0] + c[1] + c[2])) c = vec3(z), mass = 0;
    // D uses the full move to the centroid (the paper's P_i - P*_i).
    dsum += dist2(z, c.data()) / (b.H[v] * b.H[v]);
    e.free_ids.push_back(v);
    e.z.insert(e.z.end(), z, z + 3);
    e.c.insert(e.c.end(), c.begin(), c.end());
    e.mass.push_back(mass);
  }
  e.energy = s.energy;
  s.D = s.nb_free ? dsum / s.nb_free : 0.0;
  return e;
}

std::vector<double> with_free_positions(const std::vector<double>& xyz,
                                        const std::vector<int>& free_ids,
                                        const std::vector<double>& free_xyz) {
  std::vector<double> out(xyz);
  for (std::size_t i = 0; i < free_ids.size(); ++i)
    for (int d = 0; d < 3; ++d) out[3 * free_ids[i] + d] = free_xyz[3 * i + d];
  return out;
}

}  // namespace cvtmesh
