#include "bench/baselines/gmsh_optimizer.h"

#include <gmsh.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/io/gmsh_model.h"
#include "core/io/gmsh_session.h"
#include "core/io/write_mesh.h"
#include "core/mesh/renumber_vertices.h"
#include "core/util/error.h"

namespace cvtmesh {

void gmsh_optimize_mesh(MeshData& data, const std::string& method, int niter) {
  // Gmsh 4.8's optimizer silently skips volumes created through addDiscreteEntity, but runs on a
  // model read from a .msh file: go through a temporary .msh.
  char dir_tmpl[] = "/tmp/cvtmesh-gmshopt-XXXXXX";
  if (!mkdtemp(dir_tmpl))
    throw OutputError("cannot create a temporary directory for Gmsh's optimizer");
  const std::string dir = dir_tmpl, file = dir + "/mesh.msh";
  struct Cleanup {
    std::string dir, file;
    ~Cleanup() {
      std::remove(file.c_str());
      rmdir(dir.c_str());
    }
  } cleanup{dir, file};
  WriteOptions wo;
  wo.binary = true;    // exact coordinates (ASCII .msh keeps 16 significant digits only)
  wo.save_all = true;  // every element: an internal round trip, not a file for other tools
  write_mesh(data, file, wo);
  GmshSession session;
  std::string previous;
  gmsh::model::getCurrent(previous);
  MeshData out;
  try {
    gmsh_checked("Gmsh optimizer '" + method + "' failed", [&] {
      gmsh::model::add("cvtmesh_gmsh_optimize");
      gmsh::merge(file);
      gmsh::option::setNumber("General.NumThreads", 1);
      gmsh::model::mesh::optimize(method, true, niter);
    });
    out = mesh_from_gmsh(data.dim, "the mesh optimized by Gmsh");
  } catch (...) {
    gmsh::model::remove();
    if (!session.owns() && !previous.empty()) gmsh::model::setCurrent(previous);
    throw;
  }
  gmsh::model::remove();
  if (!session.owns() && !previous.empty()) gmsh::model::setCurrent(previous);
  out.model().source = data.model().source;
  renumber_vertices_like(out.tet, data.tet);
  data = std::move(out);
}

}  // namespace cvtmesh
