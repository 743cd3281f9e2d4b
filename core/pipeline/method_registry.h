// The named methods users pick, 2D and 3D, in menu order: name, dimension, what it runs, help.
// Menus (CLI --help, the GUI panel, the Python docstring) and the docs read this one table; a new
// method is one row here and its runner (docs/architecture.md, "Adding a method").
#pragma once
#include <string>
#include <vector>

#include "core/mesh/tet_mesh.h"

namespace cvtmesh {

struct OptimizeOptions;
struct OptimizeResult;

// A 3D method: optimizes mesh in place with the (validated, resolved) options and fills the
// result's iterations/converged/lloyd fields. 2D methods all run through optimize_2d.
using Run3 = void (*)(TetMesh& mesh, const OptimizeOptions& options, OptimizeResult& result);

struct MethodInfo {
  std::string name;
  int dim = 3;          // 2 or 3
  Run3 run3 = nullptr;  // 3D: the runner (core/pipeline/optimize.cpp); 2D: null (optimize_2d)
  std::string help;     // one line, the paper's words
};

// Every method, 3D first then 2D, each dimension in menu order (its first is its default).
const std::vector<MethodInfo>& method_registry();

// The method named `name` for dimension dim, or null.
const MethodInfo* find_method(const std::string& name, int dim);

// The names of dimension dim's methods in menu order (empty for another dimension).
std::vector<std::string> methods_for_dim(int dim);

// The default method of dimension dim (the first of its menu).
std::string default_method(int dim);

// "name: help" lines of dimension dim's methods (0: both), for --help and docstrings.
std::string methods_help(int dim = 0);

}  // namespace cvtmesh
