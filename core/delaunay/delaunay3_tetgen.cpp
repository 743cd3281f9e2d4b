// The TetGen 1.5 backend of Delaunay3: constrained Delaunay tetrahedralization of the piecewise
// linear complex made of the constrained triangles, with every mesh vertex inserted.
#include <tetgen.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/delaunay/component_seeds.h"
#include "core/delaunay/delaunay3.h"
#include "core/delaunay/tetrahedralize_isolated.h"
#include "core/geometry/tetgen_library.h"
#include "core/geometry/predicates.h"
#include "core/mesh/build_adjacency.h"
#include "core/util/error.h"

namespace cvtmesh {

Delaunay3Stats tetgen_rebuild(TetMesh& m, const std::string& switches, const std::string& stage) {
  Delaunay3Stats stats;
  const auto seeds = component_seeds(m);
  const int nv = m.nb_vertices();

  // Only the vertices a tet or a constrained triangle uses: a node no element uses (a meshed
  // wire, a duplicated CAD point) is not TetGen's to insert (it merged such duplicates and
  // "lost" them) and stays where it is, unused.
  std::vector<int> ids, id_of(nv, -1);
  for (int v : m.tets)
    if (v >= 0 && id_of[v] < 0) id_of[v] = 0;
  for (int v : m.tris) id_of[v] = 0;
  for (int v = 0; v < nv; ++v)
    if (id_of[v] == 0) {
      id_of[v] = static_cast<int>(ids.size());
      ids.push_back(v);
    }
  const int np = static_cast<int>(ids.size());

  tetgenio in;
  in.firstnumber = 0;
  in.numberofpoints = np;
  in.pointlist = new REAL[3 * static_cast<std::size_t>(np)];
  for (int i = 0; i < np; ++i)
    for (int d = 0; d < 3; ++d) in.pointlist[3 * i + d] = m.xyz[3 * ids[i] + d];

  const int nf = m.nb_tris();
  in.numberoffacets = nf;
  in.facetlist = new tetgenio::facet[nf];
  in.facetmarkerlist = new int[nf];
  for (int f = 0; f < nf; ++f) {
    tetgenio::facet& fa = in.facetlist[f];
    tetgenio::init(&fa);
    fa.numberofpolygons = 1;
    fa.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&fa.polygonlist[0]);
    fa.polygonlist[0].numberofvertices = 3;
    fa.polygonlist[0].vertexlist = new int[3];
    for (int k = 0; k < 3; ++k) fa.polygonlist[0].vertexlist[k] = id_of[m.tris[3 * f + k]];
    in.facetmarkerlist[f] = m.tri_surface[f];
  }
  in.numberofregions = static_cast<int>(seeds.size());
  in.regionlist = new REAL[5 * seeds.size()];
  int i = 0;
  for (const auto& [tag, c] : seeds) {
    in.regionlist[5 * i + 0] = c[0];
    in.regionlist[5 * i + 1] = c[1];
    in.regionlist[5 * i + 2] = c[2];
    in.regionlist[5 * i + 3] = tag;
    in.regionlist[5 * i + 4] = -1;
    ++i;
  }
  const IsolatedTetgenOutput out = tetrahedralize_isolated(switches.c_str(), in, stage);
  const int nb_out_points = static_cast<int>(out.points.size() / 3);
  const int nb_out_tets = static_cast<int>(out.tets.size() / 4);
  if (nb_out_points < np)
    throw InvariantError("TetGen lost input points (" + std::to_string(np - nb_out_points) + ")");

  std::set<int> regions;
  for (const auto& [tag, c] : seeds) regions.insert(tag);
  // Steiner points (interior only, thanks to -Y) are appended as free vertices, those of kept
  // tets only (TetGen also refines a hole's tets, which are dropped), each in the region of the
  // first tet that uses it. Regions of the new tets are those of the seeds.
  std::vector<int> steiner_id(nb_out_points - np, -1);
  auto vertex_of = [&](int p, int region) {
    if (p < np) return ids[p];
    int& id = steiner_id[p - np];
    if (id < 0) {
      id = m.nb_vertices();
      m.xyz.insert(m.xyz.end(), out.points.begin() + 3 * p, out.points.begin() + 3 * p + 3);
      m.vclass.push_back(VertexClass{3, region});
      if (!m.node_tags.empty()) m.node_tags.push_back(0);
    }
    return id;
  };
  m.tets.clear();
  m.tet_region.clear();
  m.tet_tags.clear();
  for (int t = 0; t < nb_out_tets; ++t) {
    const int region = static_cast<int>(out.attributes[t]);
    if (!regions.count(region)) {
      ++stats.nb_dropped_tets;
      continue;
    }
    int v[4];
    for (int k = 0; k < 4; ++k) v[k] = vertex_of(out.tets[4 * t + k], region);
    if (orient3d(m.point(v[0]), m.point(v[1]), m.point(v[2]), m.point(v[3])) < 0)
      std::swap(v[2], v[3]);
    m.tets.insert(m.tets.end(), v, v + 4);
    m.tet_region.push_back(region);
  }
  stats.nb_steiner = m.nb_vertices() - nv;
  build_adjacency(m);
  return stats;
}

namespace {

class TetgenDelaunay3 final : public Delaunay3 {
 public:
  std::string name() const override { return "tetgen"; }

  // p: PLC; Y: keep the boundary mesh (no Steiner point on it); A: region attributes;
  // z: 0-based; Q: quiet; M: do not merge coplanar facets; O0: no mesh optimization. TetGen
  // optimizes a PLC's mesh by default (-O2: flips for quality), which leaves faces that are not
  // locally Delaunay (~190 on a 5x5x5 lattice, 2 in 3k tets on cube_sphere): the CVT needs the
  // constrained Delaunay tetrahedralization itself (tests/delaunay/delaunay3_degenerate_test).
  // In a child process (tetrahedralize_isolated): a crash inside TetGen becomes an
  // InvariantError, and optimize() goes on with local operations only.
  Delaunay3Stats retetrahedralize(TetMesh& m) override {
    return tetgen_rebuild(m, "pYAzQMO0", "the Delaunay rebuild of the CVT (retetrahedralize)");
  }
};

}  // namespace

std::unique_ptr<Delaunay3> Delaunay3::create(const std::string& name) {
  if (name == "tetgen") return std::make_unique<TetgenDelaunay3>();
  throw std::invalid_argument("unknown Delaunay backend '" + name + "' (available: tetgen)");
}

}  // namespace cvtmesh
