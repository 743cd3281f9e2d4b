// In-process scripting from C++: build or open a model with the Gmsh SDK, mesh it, and optimize
// the current model's mesh in place with cvtmesh::gmsh_optimize. Entities and physical groups
// stay; the optimized mesh and its quality views are what gmsh::write sees afterwards.
//
//   optimize_current_model [model.geo] [out.msh] [method]
//
// Build: against the installed package, this directory is a CMake project (docs/examples/
// CMakeLists.txt: find_package(cvtmesh), target cvtmesh::gmsh_frontend); in the source tree,
// plugin/CMakeLists.txt builds it as cvtmesh_example_optimize.
#include <gmsh.h>

#include <exception>
#include <iostream>
#include <string>

#include "plugin/gmsh_inprocess.h"

int main(int argc, char** argv) {
#ifdef CVTMESH_SOURCE_DIR
  const std::string model = argc > 1 ? argv[1] : CVTMESH_SOURCE_DIR "/geo/cube_sphere.geo";
#else
  if (argc < 2) {
    std::cerr << "usage: optimize_current_model model.geo [out.msh] [method]\n";
    return 1;
  }
  const std::string model = argv[1];
#endif
  const std::string out = argc > 2 ? argv[2] : "cube_sphere_cvt.msh";
  gmsh::initialize();
  try {
    gmsh::option::setNumber("General.Terminal", 1);
    gmsh::option::setNumber("Mesh.MeshSizeFactor", 2);  // a coarse mesh: the example runs fast
    gmsh::open(model);
    gmsh::model::mesh::generate(3);

    cvtmesh::GmshOptimizeOptions options;
    // Empty: the first of cvtmesh::methods_for_dim(3), the paper's best available.
    options.optimize.method = argc > 3 ? argv[3] : "";
    options.optimize.max_iterations = 20;
    options.quality_views = true;
    options.optimize.progress = [](const cvtmesh::OptimizeProgress& p) {
      std::cout << p.phase << " " << p.iteration << ": Q avg " << p.q_avg << "\n";
    };
    const cvtmesh::GmshOptimizeResult r = cvtmesh::gmsh_optimize(options);
    std::cout << r.table().to_text();

    // The model now holds the optimized mesh; write it with the quality views.
    gmsh::option::setNumber("Mesh.SaveAll", 0);  // physical groups decide what is saved
    gmsh::write(out);
    gmsh::option::setNumber("PostProcessing.SaveMesh", 0);  // the mesh is in the file already
    gmsh::option::setNumber("PostProcessing.SaveInterpolationMatrices", 0);
    for (int v : r.views) gmsh::view::write(v, out, true);
    std::cout << "wrote " << out << "\n";
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    gmsh::finalize();
    return 1;
  }
  gmsh::finalize();
  return 0;
}
