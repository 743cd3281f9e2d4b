// The library without Gmsh's scripting: read a mesh or model, optimize it, write it, and print
// the paper's quality table before and after. Only the umbrella header is included.
//
//   read_optimize_write IN OUT [method]     e.g. read_optimize_write cube_sphere.geo out.msh
#include <cvtmesh/cvtmesh.h>

#include <exception>
#include <iostream>

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: read_optimize_write IN OUT [method]\n";
    return 1;
  }
  try {
    cvtmesh::MeshData mesh = cvtmesh::read_mesh(argv[1]);
    cvtmesh::OptimizeOptions options;        // defaults from the option schema
    if (argc > 3) options.method = argv[3];  // empty: the dimension's default method
    options.max_iterations = 20;
    const cvtmesh::OptimizeResult r = cvtmesh::optimize(mesh, options);
    cvtmesh::write_mesh(mesh, argv[2]);
    cvtmesh::QualityTable table;
    table.columns = {r.before, r.after};
    table.columns[0].label = "input";
    table.columns[1].label = r.method;
    std::cout << table.to_text() << "wrote " << argv[2] << "\n";
  } catch (const cvtmesh::InputError& e) {
    std::cerr << "bad input: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
