// Constrained boundary Delaunay tetrahedralization behind one interface (geogram
// Delaunay::create style): the CVT loop talks only to this, so an incremental or parallel backend
// can replace a from-scratch rebuild without touching the loop.
#pragma once
#include <memory>
#include <string>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct Delaunay3Stats {
  int nb_steiner =
      0;  // points the backend added to kept tets (appended to the mesh, interior class)
  int nb_dropped_tets = 0;  // tets outside every region (holes) that were discarded
};

class Delaunay3 {
 public:
  virtual ~Delaunay3() = default;
  virtual std::string name() const = 0;
  // Rebuilds mesh.tets / tet_region / adj from the current vertex positions (mesh.xyz), keeping
  // every constrained triangle (mesh.tris) as a face, each tet in the region it was in before
  // (regions are identified by the old tets: the mesh must be valid on entry). Vertex ids are
  // kept; Steiner points, if the backend needs any, are appended. Throws InvariantError if the
  // boundary cannot be recovered.
  virtual Delaunay3Stats retetrahedralize(TetMesh& mesh) = 0;

  // "tetgen" (TetGen 1.5, -pY: the boundary mesh is preserved exactly).
  static std::unique_ptr<Delaunay3> create(const std::string& name = "tetgen");
};

// The TetGen rebuild behind the "tetgen" backend with other switches (they must include pYAz: a
// PLC of the constrained triangles, the boundary kept, region attributes, 0-based), run in a
// child process; `stage` names it in errors. refine_interior3 adds q.
Delaunay3Stats tetgen_rebuild(TetMesh& mesh, const std::string& switches, const std::string& stage);

}  // namespace cvtmesh
